#include "Durable/interrupt_guard.h"

namespace frep::durable
{
namespace
{

volatile std::sig_atomic_t g_interrupted = 0; // the signal's number, 0 before one arrives
int g_depth = 0; // nested guards (main's around a command's own) install once

void on_interrupt(int signal)
{
  g_interrupted = signal;
}

} // namespace

InterruptGuard::InterruptGuard()
{
  if (g_depth++ > 0)
  {
    return;
  }
  g_interrupted = 0;
  struct sigaction action
  {
  };
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND; // the second signal has the default effect
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

InterruptGuard::~InterruptGuard()
{
  if (--g_depth > 0)
  {
    return;
  }
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

bool InterruptGuard::interrupted()
{
  return g_interrupted != 0;
}

int InterruptGuard::signal_number()
{
  return g_interrupted;
}

void InterruptGuard::throw_if_interrupted()
{
  if (interrupted())
  {
    throw Interrupted();
  }
}

} // namespace frep::durable
