// A one-line progress bar on standard error, shown only when standard error is a terminal (in
// logs and pipes it would be noise). Updates are cheap: the line is redrawn when the percentage
// changes.
#pragma once

#include <string>

namespace frepkit
{

class ProgressBar
{
public:
  /// `enabled` false (--quiet) hides it; so does a standard error that is not a terminal.
  ProgressBar(std::string label, bool enabled);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(double fraction);
  /// Clears the line (called by the destructor too).
  void finish();

private:
  std::string label_;
  bool shown_ = false;
  int percent_ = -1;
};

} // namespace frepkit
