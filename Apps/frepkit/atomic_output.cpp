#include "atomic_output.h"

#include "interrupt_guard.h"
#include "user_error.h"

#include "Media/durable_file.h"

#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace frepkit
{

AtomicOutput::AtomicOutput(std::string path)
  : path_(std::move(path))
{
  if (path_ == "-")
  {
    return;
  }
  temporary_ = path_ + ".tmp-" + std::to_string(::getpid());
  file_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!file_)
  {
    throw UserError(path_ + ": cannot write (temporary file " + temporary_ + ")");
  }
}

AtomicOutput::~AtomicOutput()
{
  if (!temporary_.empty() && !committed_)
  {
    file_.close();
    std::remove(temporary_.c_str());
  }
}

std::ostream& AtomicOutput::stream()
{
  return temporary_.empty() ? std::cout : static_cast<std::ostream&>(file_);
}

void AtomicOutput::commit()
{
  if (temporary_.empty())
  {
    std::cout.flush();
    committed_ = true;
    return;
  }
  file_.close();
  if (!file_)
  {
    throw UserError(path_ + ": cannot write the output file");
  }
  // After SIGINT/SIGTERM nothing more is put in place: the old file stays, the destructor
  // removes the temporary. (Data written after the signal may also be short: an EINTR on a
  // pipe read looks like the end of the input.)
  InterruptGuard::throw_if_interrupted();
  // The data on disk before the file gets its name, the name on disk before we report success.
  if (const std::string problem = frep::media::durable_rename(temporary_, path_); !problem.empty())
  {
    throw UserError(path_ + ": cannot write the output file (" + problem + ")");
  }
  committed_ = true;
}

} // namespace frepkit
