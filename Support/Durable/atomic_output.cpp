#include "Durable/atomic_output.h"

#include "Durable/interrupt_guard.h"

#include <iostream>

namespace frep::durable
{

AtomicOutput::AtomicOutput(std::string path)
  : path_(std::move(path))
{
  if (path_ == "-")
  {
    return;
  }
  pending_ = std::make_unique<PendingFile>(path_);
  if (!pending_->error().empty())
  {
    throw OutputError(path_ + ": cannot write (" + pending_->error() + ")");
  }
  file_.open(pending_->temporary(), std::ios::binary | std::ios::trunc);
  if (!file_)
  {
    throw OutputError(
      path_ + ": cannot write (temporary file " + pending_->temporary().string() + ")");
  }
}

// file_ is declared after pending_, so it is closed before the PendingFile removes the temporary.
AtomicOutput::~AtomicOutput() = default;

std::ostream& AtomicOutput::stream()
{
  return pending_ ? static_cast<std::ostream&>(file_) : std::cout;
}

void AtomicOutput::commit()
{
  if (!pending_)
  {
    std::cout.flush();
    return;
  }
  file_.close();
  if (!file_)
  {
    throw OutputError(path_ + ": cannot write the output file");
  }
  InterruptGuard::throw_if_interrupted();
  if (const std::string problem = pending_->commit(); !problem.empty())
  {
    throw OutputError(path_ + ": cannot write the output file (" + problem + ")");
  }
}

} // namespace frep::durable
