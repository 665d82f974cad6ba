#include "Eval/detail/code_memory.h"

#include <algorithm>
#include <cstring>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#define FREP_CODE_MEMORY_LINUX 1
#endif

namespace frep::eval
{

#if defined(FREP_CODE_MEMORY_LINUX)

namespace
{

std::size_t round_to_pages(std::size_t bytes)
{
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return (std::max<std::size_t>(bytes, 1) + page - 1) / page * page;
}

/// The two views of a fresh memfd of `size` bytes, or false (the fd is closed either way: the
/// mappings keep the pages).
bool map_dual(std::size_t size, void*& writable, void*& executable)
{
  const int fd = memfd_create("frepkit-jit", MFD_CLOEXEC);
  if (fd < 0)
  {
    return false;
  }
  bool ok = ftruncate(fd, static_cast<off_t>(size)) == 0;
  writable = ok ? mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0) : MAP_FAILED;
  ok = writable != MAP_FAILED;
  executable = ok ? mmap(nullptr, size, PROT_READ | PROT_EXEC, MAP_SHARED, fd, 0) : MAP_FAILED;
  if (ok && executable == MAP_FAILED)
  {
    munmap(writable, size);
    ok = false;
  }
  close(fd);
  return ok;
}

} // namespace

std::shared_ptr<CodeMemory> CodeMemory::make(std::size_t bytes)
{
  std::shared_ptr<CodeMemory> memory(new CodeMemory());
  memory->size_ = round_to_pages(bytes);
  void* writable = nullptr;
  void* executable = nullptr;
  if (map_dual(memory->size_, writable, executable))
  {
    memory->dual_ = true;
  }
  else
  {
    writable = mmap(nullptr, memory->size_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
      -1, 0);
    if (writable == MAP_FAILED)
    {
      return nullptr;
    }
    executable = writable;
  }
  memory->writable_ = static_cast<std::uint8_t*>(writable);
  memory->executable_ = executable;
  return memory;
}

CodeMemory::~CodeMemory()
{
  munmap(writable_, size_);
  if (dual_)
  {
    munmap(const_cast<void*>(executable_), size_);
  }
}

bool CodeMemory::load(std::span<const std::uint8_t> code)
{
  if (code.size() > size_)
  {
    return false;
  }
  if (dual_)
  {
    // x86 keeps instruction fetch coherent with stores through another mapping of the page; the
    // code runs on this thread after the copy, or on others after the caller's synchronisation.
    std::memcpy(writable_, code.data(), code.size());
    return true;
  }
  if (mprotect(writable_, size_, PROT_READ | PROT_WRITE) != 0)
  {
    return false;
  }
  std::memcpy(writable_, code.data(), code.size());
  return mprotect(writable_, size_, PROT_READ | PROT_EXEC) == 0;
}

#else

std::shared_ptr<CodeMemory> CodeMemory::make(std::size_t)
{
  return nullptr; // no JIT off Linux
}

CodeMemory::~CodeMemory() = default;

bool CodeMemory::load(std::span<const std::uint8_t>)
{
  return false;
}

#endif

} // namespace frep::eval
