#include "progress_bar.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace frepkit
{

ProgressBar::ProgressBar(std::string label, bool enabled)
  : label_(std::move(label))
  , shown_(enabled && ::isatty(STDERR_FILENO) == 1)
{
}

ProgressBar::~ProgressBar()
{
  finish();
}

void ProgressBar::update(double fraction)
{
  if (!shown_)
  {
    return;
  }
  const int percent = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 100.0);
  // Workers report in any order: the bar only moves forward.
  if (percent <= percent_)
  {
    return;
  }
  percent_ = percent;
  constexpr int kWidth = 40;
  const int filled = percent * kWidth / 100;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kWidth - filled), '.');
  std::fprintf(stderr, "\r%s [%s] %3d%%", label_.c_str(), bar.c_str(), percent);
  std::fflush(stderr);
}

void ProgressBar::finish()
{
  if (shown_ && percent_ >= 0)
  {
    // Erase the bar so that the report starts on a clean line.
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 48, "");
    std::fflush(stderr);
  }
  percent_ = -1;
}

} // namespace frepkit
