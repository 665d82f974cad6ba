// An output file that becomes its target only when complete: the one temporary of the project.
// It is created beside the target (the final rename must not cross file systems), named
// TARGET.tmp-PID-N, removed by the destructor unless committed, and put in place by commit()
// with durable_rename. Writers that need a path (libsndfile, the ffmpeg program, Qt's image
// writer) write to temporary(); writers of a stream use AtomicOutput, which holds one.
#pragma once

#include <filesystem>
#include <string>

namespace frep::durable
{

class PendingFile
{
public:
  /// Creates the temporary (exclusively, mode 0666 less the umask, empty). error() says why
  /// when it could not be created; then temporary() is empty and commit() fails.
  explicit PendingFile(std::filesystem::path target);
  /// Removes the temporary unless commit() succeeded.
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temporary_; }
  /// Why the temporary could not be created; empty when it was.
  const std::string& error() const { return error_; }
  bool committed() const { return committed_; }

  /// The temporary, complete and closed by its writer, becomes the target: fsync, rename, fsync
  /// of the directory. Refused after SIGINT/SIGTERM under an InterruptGuard (the old target
  /// stays). Empty on success, else what failed (the destructor then removes the temporary).
  std::string commit();

private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::string error_;
  bool committed_ = false;
};

/// The temporary's name for `target`: TARGET.tmp-PID-N, N counting this process's temporaries
/// (so two outputs of one run never share one).
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

} // namespace frep::durable
