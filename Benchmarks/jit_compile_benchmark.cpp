// What compiling a tape to machine code costs (eval::JitKernel::compile): wall time per tape
// instruction, the code's size, the slots kept in the stack frame. This is the figure behind
// LazyKernel's threshold (a kernel must be given enough samples to pay for itself). The model is
// any file frepkit reads (.hf, .vm); its default object's tape with every coordinate free.
//
// Usage: frep_jit_compile_benchmark MODEL [--repeat 21]
// Prints the median, fastest and slowest of the repeats; each compiles into fresh code memory
// (the first compile of a LazyKernel), which is what the throttled callers pay.
#include "benchmark_cli.h"

#include "Eval/detail/jit_kernel.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: frep_jit_compile_benchmark MODEL [--repeat N]\n";
    return 1;
  }
  const std::string path = argv[1];
  int repeat = 21;
  for (int i = 2; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    if (option != "--repeat")
    {
      std::cerr << "unknown option " << option << "\n";
      return 1;
    }
    repeat = std::max(1, std::stoi(argv[i + 1]));
  }
  if (!frep::eval::jit_available())
  {
    std::cerr << "this CPU has no AVX2: nothing to compile\n";
    return 1;
  }
  const auto model = frep::bench::compile_model_file(path);
  if (!model)
  {
    return 1;
  }
  const auto tape = model->tape();
  const std::size_t instructions = tape->code.size();
  std::vector<double> seconds;
  std::size_t code_size = 0, spilled = 0;
  for (int r = 0; r < repeat; ++r)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const auto kernel = frep::eval::JitKernel::compile(*tape);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (!kernel)
    {
      std::cerr << path << ": the tape does not compile (an opaque call, or its frame is too "
                           "large)\n";
      return 1;
    }
    code_size = kernel->code_size();
    spilled = kernel->spilled_slots();
  }
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  std::printf("%s: %zu instructions, %zu slots; compile median %.3f ms (%.0f ns per instruction), "
              "fastest %.3f ms, slowest %.3f ms over %d; %zu bytes of code, %zu slots spilled\n",
    path.c_str(),
    instructions,
    static_cast<std::size_t>(tape->slot_count),
    1e3 * median,
    1e9 * median / static_cast<double>(std::max<std::size_t>(1, instructions)),
    1e3 * seconds.front(),
    1e3 * seconds.back(),
    repeat,
    code_size,
    spilled);
  return 0;
}
