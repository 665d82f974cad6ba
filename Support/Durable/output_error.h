// What an output of FRepKit::Durable reports when it cannot be written or put in place, and a
// run stopped by a signal. Programs that report by exception (frepkit) catch OutputError beside
// their own user errors: both are one message and no output.
#pragma once

#include <stdexcept>
#include <string>

namespace frep::durable
{

class OutputError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// A run stopped by SIGINT/SIGTERM (InterruptGuard): nothing more is put in place. An
/// OutputError, so that every place that cleans up on a failed output does so here too.
class Interrupted : public OutputError
{
public:
  explicit Interrupted(const std::string& what = "interrupted; no output written")
    : OutputError(what)
  {
  }
};

} // namespace frep::durable
