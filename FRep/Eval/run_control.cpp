#include "Eval/run_control.h"

#include "Eval/thread_pool.h"

namespace frep
{

std::shared_ptr<ThreadPool> RunControl::thread_pool() const
{
  return pool ? pool : std::make_shared<ThreadPool>(threads);
}

} // namespace frep
