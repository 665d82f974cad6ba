// A program that leaks from its own code, on purpose: lsan_report_check.py must fail on it
// (ctest FRepStudio::LeakCheckFailsOnOurLeak). It shows that LeakSanitizer is
// really preloaded and that a leak of ours is not taken for a third-party one.
#include <cstdio>

namespace
{

int* volatile g_block = nullptr;

[[gnu::noinline]] void leak()
{
  g_block = new int[64];
  g_block[0] = 1;
  g_block = nullptr; // the only pointer to the block is gone
}

} // namespace

int main()
{
  leak();
  std::puts("leaked 256 bytes");
  return 0;
}
