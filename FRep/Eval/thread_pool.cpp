#include "Eval/thread_pool.h"

#include <algorithm>

namespace frep
{

namespace
{
// The pool whose body the current thread is running, to run nested calls inline instead of
// deadlocking on the submit mutex.
thread_local const ThreadPool* tls_running_pool = nullptr;
thread_local int tls_running_slot = 0;
} // namespace

ThreadPool::ThreadPool(int threads)
{
  if (threads <= 0)
  {
    threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  }
  workers_.reserve(static_cast<std::size_t>(threads - 1));
  for (int slot = 1; slot < threads; ++slot)
  {
    workers_.emplace_back([this, slot] { worker_loop(slot); });
  }
}

ThreadPool::~ThreadPool()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_)
  {
    worker.join();
  }
}

void ThreadPool::run_share(int slot)
{
  const ThreadPool* outer = tls_running_pool;
  const int outer_slot = tls_running_slot;
  tls_running_pool = this;
  tls_running_slot = slot;
  for (;;)
  {
    std::size_t index = 0;
    {
      // Indices are coarse (blocks of points), so one lock per index costs nothing measurable
      // and keeps the skip-after-exception logic simple.
      std::lock_guard<std::mutex> lock(mutex_);
      if (next_ >= count_ || error_)
      {
        break;
      }
      index = next_++;
    }
    try
    {
      (*body_)(index, slot);
    }
    catch (...)
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_)
      {
        error_ = std::current_exception();
      }
    }
  }
  tls_running_pool = outer;
  tls_running_slot = outer_slot;
}

void ThreadPool::worker_loop(int slot)
{
  std::size_t seen = 0;
  for (;;)
  {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_)
      {
        return;
      }
      seen = generation_;
      ++busy_workers_;
    }
    run_share(slot);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      --busy_workers_;
    }
    done_.notify_all();
  }
}

void ThreadPool::parallel_for(std::size_t count,
  const std::function<void(std::size_t index, int slot)>& body)
{
  if (count == 0)
  {
    return;
  }
  if (workers_.empty() || count == 1 || tls_running_pool == this)
  {
    // Serial: the caller is the only participant (slot 0, or its own slot when nested; the
    // nested body then shares that slot's scratch, which the outer body must allow).
    const int slot = tls_running_pool == this ? tls_running_slot : 0;
    for (std::size_t i = 0; i < count; ++i)
    {
      body(i, slot);
    }
    return;
  }
  std::lock_guard<std::mutex> submit(submit_mutex_);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    body_ = &body;
    count_ = count;
    next_ = 0;
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  run_share(0);
  std::exception_ptr error;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    // No index is left to hand out (all taken, or skipped after an exception): wait for the
    // workers still running one. A worker that wakes up late for this job finds count_ == 0
    // and leaves without touching body_.
    done_.wait(lock, [&] { return busy_workers_ == 0; });
    body_ = nullptr;
    count_ = 0;
    next_ = 0;
    error = error_;
    error_ = nullptr;
  }
  if (error)
  {
    std::rethrow_exception(error);
  }
}

} // namespace frep
