// Internal: run a job over independent work items on a few threads. Items are handed out from an
// atomic counter, so the split depends on timing, but every item is computed the same way
// whatever thread runs it: callers keep results deterministic by writing per item only.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace frep::render::detail
{

inline int resolve_thread_count(int requested)
{
  if (requested > 0)
  {
    return requested;
  }
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware == 0 ? 1 : static_cast<int>(hardware);
}

/// job(item) for item in [0, count), on up to `threads` threads (the caller's included).
template<class Job>
void parallel_items(std::size_t count, int threads, const Job& job)
{
  const std::size_t workers = std::min<std::size_t>(std::max(threads, 1), count);
  if (workers <= 1)
  {
    for (std::size_t i = 0; i < count; ++i)
    {
      job(i);
    }
    return;
  }
  std::atomic<std::size_t> next{ 0 };
  const auto run = [&]
  {
    for (std::size_t i = next.fetch_add(1); i < count; i = next.fetch_add(1))
    {
      job(i);
    }
  };
  std::vector<std::jthread> pool;
  pool.reserve(workers - 1);
  for (std::size_t t = 1; t < workers; ++t)
  {
    pool.emplace_back(run);
  }
  run();
}

} // namespace frep::render::detail
