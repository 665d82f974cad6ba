// Output that never leaves a half-written file: written under a temporary name next to the
// target and, when complete, synced and renamed over it (frep::media::durable_rename: the data
// and the new name reach the disk before commit() returns). "-" means standard output.
#pragma once

#include <fstream>
#include <ostream>
#include <string>

namespace frepkit
{

class AtomicOutput
{
public:
  /// Opens the temporary file (or binds stdout for "-"). Throws UserError if it cannot.
  explicit AtomicOutput(std::string path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ostream& stream();
  /// Flushes, closes, syncs and renames the temporary file to the target, then syncs the
  /// directory. Throws UserError on failure.
  void commit();

private:
  std::string path_;
  std::string temporary_;
  std::ofstream file_;
  bool committed_ = false;
};

} // namespace frepkit
