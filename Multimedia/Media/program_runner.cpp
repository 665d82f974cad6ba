#include "Media/program_runner.h"

#include "Media/detail/system_message.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>

extern char** environ; // POSIX: the process environment, handed unchanged to the child

namespace frep::media
{
namespace
{

using detail::system_message;

bool is_executable_file(const std::filesystem::path& path)
{
  struct stat status
  {
  };
  return ::stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode) &&
         ::access(path.c_str(), X_OK) == 0;
}

// A pipe whose ends close automatically; both ends are close-on-exec, and the child gets its
// copies through posix_spawn_file_actions_adddup2 only.
struct Pipe
{
  int read_end = -1;
  int write_end = -1;
  Pipe() = default;
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  ~Pipe()
  {
    close_read();
    close_write();
  }
  bool open()
  {
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0)
      return false;
    read_end = ends[0];
    write_end = ends[1];
    return true;
  }
  void close_read()
  {
    if (read_end >= 0)
      ::close(read_end);
    read_end = -1;
  }
  void close_write()
  {
    if (write_end >= 0)
      ::close(write_end);
    write_end = -1;
  }
};

struct SpawnActions
{
  posix_spawn_file_actions_t actions;
  SpawnActions() { posix_spawn_file_actions_init(&actions); }
  SpawnActions(const SpawnActions&) = delete;
  SpawnActions& operator=(const SpawnActions&) = delete;
  ~SpawnActions() { posix_spawn_file_actions_destroy(&actions); }
};

} // namespace

std::optional<std::filesystem::path> find_program(std::string_view name)
{
  if (name.empty())
    return std::nullopt;
  if (name.find('/') != std::string_view::npos)
  {
    const std::filesystem::path path(name);
    return is_executable_file(path) ? std::optional(path) : std::nullopt;
  }
  const char* search_path = std::getenv("PATH");
  std::string_view directories = search_path ? search_path : "/usr/local/bin:/usr/bin:/bin";
  while (true)
  {
    const std::size_t colon = directories.find(':');
    std::string_view directory = directories.substr(0, colon);
    if (directory.empty())
      directory = "."; // POSIX: an empty PATH entry is the current directory
    const std::filesystem::path candidate = std::filesystem::path(directory) / name;
    if (is_executable_file(candidate))
      return candidate;
    if (colon == std::string_view::npos)
      return std::nullopt;
    directories.remove_prefix(colon + 1);
  }
}

ProgramResult run_program(const std::filesystem::path& program,
  const std::vector<std::string>& arguments,
  const std::function<void(std::string_view line)>& on_output_line,
  const std::function<bool()>& should_stop)
{
  ProgramResult result;
  const std::string name = program.string();
  Pipe output;
  Pipe errors;
  if (!output.open() || !errors.open())
  {
    result.error = "cannot create pipes for " + name + ": " + system_message(errno);
    return result;
  }

  SpawnActions spawn;
  posix_spawn_file_actions_addopen(&spawn.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&spawn.actions, output.write_end, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&spawn.actions, errors.write_end, STDERR_FILENO);

  std::vector<char*> argv;
  argv.reserve(arguments.size() + 2);
  argv.push_back(const_cast<char*>(name.c_str()));
  for (const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);

  pid_t child = -1;
  if (const int status =
        ::posix_spawn(&child, name.c_str(), &spawn.actions, nullptr, argv.data(), environ);
      status != 0)
  {
    result.error = "cannot run " + name + ": " + system_message(status);
    return result;
  }
  // Only the child writes: without closing our copies, the reads below would never see EOF.
  output.close_write();
  errors.close_write();

  std::string pending_line;
  pollfd fds[2] = { { output.read_end, POLLIN, 0 }, { errors.read_end, POLLIN, 0 } };
  int open_count = 2;
  char buffer[4096];
  bool stopping = false;
  while (open_count > 0)
  {
    // With a stop to watch for, wake up now and then even when the program is silent.
    const int ready = ::poll(fds, 2, should_stop ? 100 : -1);
    if (ready < 0)
    {
      if (errno == EINTR)
        continue;
      result.error = "waiting for output of " + name + ": " + system_message(errno);
      break;
    }
    if (!stopping && should_stop && should_stop())
    {
      stopping = true; // asked once; the program ends and closes its pipes
      ::kill(child, SIGTERM);
    }
    for (int i = 0; i < 2; ++i)
    {
      if (fds[i].fd < 0 || fds[i].revents == 0)
        continue;
      const ssize_t count = ::read(fds[i].fd, buffer, sizeof buffer);
      if (count < 0 && errno == EINTR)
        continue;
      if (count <= 0) // EOF (or an error: nothing more will come from this pipe)
      {
        fds[i].fd = -1; // poll ignores negative descriptors; the Pipe still closes it
        --open_count;
        continue;
      }
      const std::string_view chunk(buffer, static_cast<std::size_t>(count));
      if (i == 1)
      {
        result.standard_error.append(chunk);
        continue;
      }
      result.standard_output.append(chunk);
      if (!on_output_line)
        continue;
      pending_line.append(chunk);
      std::size_t start = 0;
      for (std::size_t end; (end = pending_line.find('\n', start)) != std::string::npos;
           start = end + 1)
        on_output_line(std::string_view(pending_line).substr(start, end - start));
      pending_line.erase(0, start);
    }
  }
  if (on_output_line && !pending_line.empty())
    on_output_line(pending_line);

  // Closed before waiting: should reading have failed, a child still writing gets EPIPE
  // instead of blocking on a full pipe while we wait for it.
  output.close_read();
  errors.close_read();
  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    if (errno != EINTR)
    {
      result.error = "waiting for " + name + ": " + system_message(errno);
      return result;
    }
  if (stopping)
  {
    result.exit_code = 128 + SIGTERM;
    result.error = name + " was stopped";
    result.stopped = true;
  }
  else if (WIFEXITED(status))
    result.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status))
  {
    result.exit_code = 128 + WTERMSIG(status);
    result.error = name + " was killed by signal " + std::to_string(WTERMSIG(status));
  }
  return result;
}

} // namespace frep::media
