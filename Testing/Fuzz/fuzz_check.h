// The harnesses' oracle: a broken property aborts (libFuzzer then saves the input as a crash,
// and the replay driver's test fails), with the property printed first.
#pragma once

#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition, what)                                                            \
  do                                                                                           \
  {                                                                                            \
    if (!(condition))                                                                          \
    {                                                                                          \
      std::fprintf(stderr, "fuzz oracle failed: %s (%s) at %s:%d\n", what, #condition,        \
        __FILE__, __LINE__);                                                                   \
      std::abort();                                                                            \
    }                                                                                          \
  } while (false)
