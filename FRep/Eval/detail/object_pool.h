// A pool of per-thread workers (evaluators, walkers) behind a thread-safe function: each call
// borrows one of its own (made on demand, kept for the next call), so forms that may run on any
// thread, like a user function's, never share an evaluator's scratch. Used by Shapes'
// tape_function and Project's projection.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace frep::eval
{

template<class T>
class ObjectPool
{
public:
  explicit ObjectPool(std::function<std::unique_ptr<T>()> make)
    : make_(std::move(make))
  {
  }

  /// f(worker) with a worker no other thread holds meanwhile; returns what f returns.
  template<class F>
  auto with(F&& f)
  {
    std::unique_ptr<T> worker;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!free_.empty())
      {
        worker = std::move(free_.back());
        free_.pop_back();
      }
    }
    if (!worker)
      worker = make_();
    // Given back even when f throws (a user function's form may report failure by throwing).
    struct GiveBack
    {
      ObjectPool& pool;
      std::unique_ptr<T>& worker;
      ~GiveBack()
      {
        std::lock_guard<std::mutex> lock(pool.mutex_);
        pool.free_.push_back(std::move(worker));
      }
    } give_back{ *this, worker };
    return f(*worker);
  }

private:
  std::function<std::unique_ptr<T>()> make_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<T>> free_;
};

} // namespace frep::eval
