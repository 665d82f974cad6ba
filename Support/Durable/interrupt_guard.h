// Ctrl-C (SIGINT) or SIGTERM cancels a run instead of killing the process, so that temporary
// output files are removed and nothing half-written is left. A program installs one guard for
// the whole of a run (frepkit's main() does, around every subcommand, so the writes are covered
// too, not only the computation); long loops poll interrupted(), PendingFile::commit() (and so
// AtomicOutput) refuses to put anything in place after a signal, and the program turns the
// Interrupted exception into exit code 128 + the signal (130, 143). A second signal kills the
// process as usual.
//
// The signal is process-wide by nature, so the flag is too: without a guard, interrupted() is
// false and nothing changes (FRepStudio, the VTK classes, Python).
#pragma once

#include "Durable/output_error.h"

#include <csignal>

namespace frep::durable
{

class InterruptGuard
{
public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static bool interrupted();
  /// The signal that interrupted the run (SIGINT or SIGTERM), 0 if none.
  static int signal_number();
  /// Throws Interrupted when a signal has arrived: the check between two pieces of work.
  static void throw_if_interrupted();

private:
  struct sigaction previous_int_
  {
  };
  struct sigaction previous_term_
  {
  };
};

} // namespace frep::durable
