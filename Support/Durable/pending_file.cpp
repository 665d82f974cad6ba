#include "Durable/pending_file.h"

#include "Durable/durable_file.h"
#include "Durable/interrupt_guard.h"

#include <atomic>
#include <cerrno>
#include <fcntl.h>
#include <system_error>
#include <unistd.h>

namespace frep::durable
{

std::filesystem::path temporary_path_for(const std::filesystem::path& target)
{
  static std::atomic<unsigned> counter{ 0 };
  std::filesystem::path name = target;
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return name;
}

PendingFile::PendingFile(std::filesystem::path target)
  : target_(std::move(target))
{
  if (target_.filename().empty())
  {
    error_ = target_.string() + ": not a file name";
    return;
  }
  std::filesystem::path temporary = temporary_path_for(target_);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0)
  {
    error_ = "cannot create the temporary file " + temporary.string() + ": " +
             std::generic_category().message(errno);
    return;
  }
  ::close(fd);
  temporary_ = std::move(temporary);
}

PendingFile::~PendingFile()
{
  if (!temporary_.empty() && !committed_)
  {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

std::string PendingFile::commit()
{
  if (temporary_.empty())
  {
    return error_.empty() ? "no temporary file" : error_;
  }
  // After SIGINT/SIGTERM nothing more is put in place: the old file stays, the destructor
  // removes the temporary. (Data written after the signal may also be short: an EINTR on a
  // pipe read looks like the end of the input.)
  if (InterruptGuard::interrupted())
  {
    return "interrupted; not put in place";
  }
  std::string problem = durable_rename(temporary_, target_);
  committed_ = problem.empty();
  return problem;
}

} // namespace frep::durable
