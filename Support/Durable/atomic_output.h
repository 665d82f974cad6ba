// A stream output that never leaves a half-written file: written to a PendingFile (a temporary
// next to the target) and, when complete, synced and renamed over it (the data and the new name
// reach the disk before commit() returns). "-" means standard output. For programs that report
// by exception: failures throw OutputError, a commit after a signal throws Interrupted.
#pragma once

#include "Durable/output_error.h"
#include "Durable/pending_file.h"

#include <fstream>
#include <memory>
#include <ostream>
#include <string>

namespace frep::durable
{

class AtomicOutput
{
public:
  /// Opens the temporary file (or binds stdout for "-"). Throws OutputError if it cannot.
  explicit AtomicOutput(std::string path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ostream& stream();
  /// Flushes, closes, syncs and renames the temporary file to the target, then syncs the
  /// directory. Throws OutputError on failure, Interrupted after SIGINT/SIGTERM.
  void commit();

private:
  std::string path_;
  std::unique_ptr<PendingFile> pending_; // null for "-"
  std::ofstream file_;
};

} // namespace frep::durable
