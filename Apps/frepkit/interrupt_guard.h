// Ctrl-C (SIGINT) or SIGTERM cancels a run instead of killing the process, so that temporary
// output files are removed and nothing half-written is left. main() installs one guard for the
// whole run of every subcommand (so the writes are covered too, not only the computation); long
// loops poll interrupted(), AtomicOutput::commit() refuses to rename after a signal, and main()
// turns the Interrupted exception into exit code 128 + the signal (130, 143). A second signal
// kills the process as usual.
#pragma once

#include "user_error.h"

#include <csignal>
#include <string>

namespace frepkit
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

/// A run stopped by SIGINT/SIGTERM. A UserError, so that every place that already cleans up on
/// user errors does so here too; main() reports it with exit code 128 + the signal.
class Interrupted : public UserError
{
public:
  explicit Interrupted(const std::string& what = "interrupted; no output written")
    : UserError(what)
  {
  }
};

} // namespace frepkit
