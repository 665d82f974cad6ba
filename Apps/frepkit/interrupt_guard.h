// Ctrl-C (SIGINT) or SIGTERM during a long computation cancels it through the mesher's progress
// callback instead of killing the process, so the temporary output file is removed and nothing
// half-written is left. A second signal kills the process as usual.
#pragma once

#include <csignal>

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

private:
  struct sigaction previous_int_
  {
  };
  struct sigaction previous_term_
  {
  };
};

} // namespace frepkit
