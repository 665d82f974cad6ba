// Running an external program (ffmpeg, ffprobe) without a shell: the arguments go to the
// program as they are, so file names with spaces, quotes or `$` need no escaping.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frep::media
{

/// The executable file `name` on PATH; a name that contains '/' is taken as a path and only
/// checked. nullopt when there is no such executable.
std::optional<std::filesystem::path> find_program(std::string_view name);

struct ProgramResult
{
  int exit_code = -1;          ///< the program's exit status; 128 + signal when killed
  std::string standard_output; ///< everything it wrote to stdout
  std::string standard_error;  ///< everything it wrote to stderr
  std::string error;           ///< non-empty when it could not be started or waited for
  bool stopped = false;        ///< ended because should_stop asked (SIGTERM)
  bool ok() const { return error.empty() && exit_code == 0; }
};

/// Runs `program` with `arguments` (not including argv[0]), stdin from /dev/null, capturing
/// stdout and stderr (read concurrently, so neither pipe can fill up and stall the program).
/// `on_output_line`, if set, receives each complete stdout line as it arrives. `should_stop`, if
/// set, is polled at least every 0.1 s: when it returns true the program is sent SIGTERM and the
/// result says `stopped`. Never throws; blocks until the program ends.
ProgramResult run_program(const std::filesystem::path& program,
  const std::vector<std::string>& arguments,
  const std::function<void(std::string_view line)>& on_output_line = {},
  const std::function<bool()>& should_stop = {});

} // namespace frep::media
