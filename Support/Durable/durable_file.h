// Putting a finished output file in place so that it survives a crash: the data reaches the
// disk before the file gets its name, and the name reaches the disk before we say "written".
// The lowest step of FRepKit::Durable; PendingFile and AtomicOutput are built on it, and every
// writer of the project (frepkit, FRepStudio, the WAV writer, the movie encoder, the mapping
// file) goes through one of those, so that none of them forgets a step.
#pragma once

#include <filesystem>
#include <string>

namespace frep::durable
{

/// fsync(temporary), rename(temporary, target), fsync(target's directory). The temporary must be
/// complete and closed (or at least flushed) and lie in the target's directory, so that the
/// rename is atomic. Returns an empty string on success, else what failed (the temporary is then
/// left for the caller to remove; a failure of the last step leaves the target in place).
std::string durable_rename(const std::filesystem::path& temporary,
  const std::filesystem::path& target);

/// fsync of a directory, so that a rename or unlink inside it is on disk. Empty on success.
std::string sync_directory(const std::filesystem::path& directory);

} // namespace frep::durable
