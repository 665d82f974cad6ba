// Executable memory for one compiled kernel at a time, reusable: written through a writable view
// and run through an executable view of the same pages (a memfd mapped twice), so loading new
// code into it costs a memcpy and no system call, where a fresh mapping per kernel cost a mmap,
// an mprotect and a munmap, each a TLB shoot-down across the process's threads (on Prospero's
// tiles, ~50 us per kernel with two threads: more than the kernel saved). Without memfd (or
// where a second mapping is refused) it falls back to one mapping made writable and then
// executable again around each load. Internal to the evaluators.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

namespace frep::eval
{

class CodeMemory
{
public:
  /// At least `bytes` of executable memory (rounded up to pages); null when the system refuses.
  static std::shared_ptr<CodeMemory> make(std::size_t bytes);

  ~CodeMemory();
  CodeMemory(const CodeMemory&) = delete;
  CodeMemory& operator=(const CodeMemory&) = delete;

  /// Replaces the contents with `code` (code.size() <= capacity()); false if the system refused
  /// (the fallback's mprotect). The caller makes sure no thread runs the old code meanwhile.
  bool load(std::span<const std::uint8_t> code);
  /// The first byte of the code, executable.
  const void* entry() const { return executable_; }
  std::size_t capacity() const { return size_; }

private:
  CodeMemory() = default;

  std::size_t size_ = 0;
  std::uint8_t* writable_ = nullptr;   // == executable_ in the fallback
  const void* executable_ = nullptr;
  bool dual_ = false;                  // two views of a memfd
};

} // namespace frep::eval
