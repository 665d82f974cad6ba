// A fixed set of worker threads that run index ranges in parallel. No global instance: whoever
// needs parallelism owns a pool (or is handed one), so two models never share hidden state.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace frep
{

class ThreadPool
{
public:
  /// `threads` participants in every parallel_for: the calling thread plus threads-1 workers.
  /// 0 = std::thread::hardware_concurrency(); 1 = no workers, everything runs on the caller.
  explicit ThreadPool(int threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  /// Participants (>= 1); the `slot` passed to a body is in [0, size()).
  int size() const { return static_cast<int>(workers_.size()) + 1; }

  /// Runs body(index, slot) for every index in [0, count), spread over the participants
  /// (dynamic: each takes the next index when it is free). `slot` identifies the participant,
  /// so a body can use per-participant scratch without locks; one slot never runs two bodies at
  /// once. Returns when every index is done. If bodies throw, the remaining indices are
  /// skipped and the first exception is rethrown here. Calls from several threads are
  /// serialised; a call from inside a body runs serially on the calling participant.
  void parallel_for(std::size_t count,
    const std::function<void(std::size_t index, int slot)>& body);

private:
  void worker_loop(int slot);
  void run_share(int slot);

  std::vector<std::thread> workers_;
  std::mutex submit_mutex_; // one parallel_for at a time

  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  bool stopping_ = false;
  std::size_t generation_ = 0; // bumped per job so a worker joins each job once
  int busy_workers_ = 0;

  // The current job (valid while a parallel_for is running).
  const std::function<void(std::size_t, int)>* body_ = nullptr;
  std::size_t count_ = 0;
  std::size_t next_ = 0; // next index to hand out (under mutex_)
  std::exception_ptr error_;
};

} // namespace frep
