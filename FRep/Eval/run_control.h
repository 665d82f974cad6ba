// How a long engine call runs: on which threads, telling how far it got, stopping when asked.
// One struct for every call that may take long (the grid sampler, the mesher, the ray caster),
// so that an application wires its progress bar and its Cancel button once:
//
//   frep::RunControl run;
//   run.threads = 4;                                   // or run.pool = a shared ThreadPool
//   run.progress = [&](double f) { bar.set(f); return true; };  // false stops the call
//   run.cancel = [&] { return stop_flag.load(); };              // true stops the call
//
// Each call says on which thread it reports progress; `cancel` may be polled from any thread.
// A call that stops returns what it says it returns when cancelled (a `cancelled` flag or
// error), never a partial result as if complete.
#pragma once

#include <functional>
#include <memory>

namespace frep
{

class ThreadPool;

struct RunControl
{
  /// Worker threads (0 = all cores) when no pool is given. Default 0.
  int threads = 0;
  /// A pool to run on, shared between calls (no threads are started per call); wins over
  /// `threads`. Default none.
  std::shared_ptr<ThreadPool> pool;
  /// Called with the fraction done in [0, 1], rising to 1 when the call completes; return false
  /// to stop. Default none.
  std::function<bool(double fraction)> progress;
  /// Polled now and then, from any thread: return true to stop. Default none.
  std::function<bool()> cancel;

  /// `pool`, or a new pool of `threads` participants.
  std::shared_ptr<ThreadPool> thread_pool() const;
  /// Whether `cancel` asks to stop.
  bool cancel_requested() const { return cancel && cancel(); }
};

} // namespace frep
