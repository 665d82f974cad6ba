#include "Durable/durable_file.h"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <system_error>
#include <unistd.h>

namespace frep::durable
{
namespace
{

/// strerror's text, thread-safe (strerror is not).
std::string system_message(int error_number)
{
  return std::generic_category().message(error_number);
}

// fsync of the file or directory at `path`, opened read-only: Linux syncs the inode's data
// whatever the descriptor's mode.
std::string sync_path(const std::filesystem::path& path, int flags, const char* what)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | flags);
  if (fd < 0)
  {
    return std::string("cannot open ") + what + " " + path.string() + ": " +
           system_message(errno);
  }
  std::string problem;
  if (::fsync(fd) != 0)
  {
    problem = std::string("fsync of ") + what + " " + path.string() + ": " + system_message(errno);
  }
  ::close(fd);
  return problem;
}

} // namespace

std::string sync_directory(const std::filesystem::path& directory)
{
  return sync_path(directory.empty() ? std::filesystem::path(".") : directory, O_DIRECTORY,
    "directory");
}

std::string durable_rename(const std::filesystem::path& temporary,
  const std::filesystem::path& target)
{
  if (std::string problem = sync_path(temporary, 0, "file"); !problem.empty())
  {
    return problem;
  }
  if (::rename(temporary.c_str(), target.c_str()) != 0)
  {
    return "cannot rename " + temporary.string() + " to " + target.string() + ": " +
           system_message(errno);
  }
  return sync_directory(target.parent_path());
}

} // namespace frep::durable
