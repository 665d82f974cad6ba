#!/usr/bin/env bash
# The engine, the plain libraries, frepkit and their tests under AddressSanitizer and
# UndefinedBehaviorSanitizer, and the fuzz harnesses (issue 18): configure the source tree with
# clang and FREPKIT_ENABLE_VTK=OFF in a build of its own, every file compiled with
# -fsanitize=address,undefined (-fno-sanitize-recover=all: a UBSan report fails like an ASan
# one) and -fsanitize=fuzzer-no-link (coverage for libFuzzer), the harnesses linked with
# -fsanitize=fuzzer; run that build's test suite, then fuzz each harness from its seeds.
# Usage: sanitizer_build_test.sh SOURCE_DIR BUILD_DIR SHARED_DIR [SECONDS_PER_HARNESS] [LAUNCHER]
set -u
source_dir=$1
build_dir=$2
shared_dir=$3
seconds=${4:-60}
launcher=${5:-}
tree="$build_dir/tree"
started=$SECONDS
mkdir -p "$build_dir"

for tool in clang clang++; do
  command -v "$tool" > /dev/null || { echo "sanitizer build: $tool not found (Scripts/install-dependencies.sh installs it)"; exit 1; }
done
# ccache when the caller's build uses it or it is installed (CI has none).
if [ -z "$launcher" ] && command -v ccache > /dev/null; then
  launcher=ccache
fi

# Debug keeps assertions; -O1 keeps the build and the runs fast enough; line tables give the
# sanitizers' stack traces file:line.
flags="-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all -fsanitize=fuzzer-no-link"
configure=(cmake -S "$source_dir" -B "$tree" -DCMAKE_BUILD_TYPE=Debug
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
  "-DCMAKE_C_FLAGS_DEBUG=$flags" "-DCMAKE_CXX_FLAGS_DEBUG=$flags"
  "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined"
  "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=address,undefined"
  "-DCMAKE_MODULE_LINKER_FLAGS=-fsanitize=address,undefined"
  -DFREPKIT_ENABLE_VTK=OFF -DFREPKIT_BUILD_BENCHMARKS=OFF -DFREPKIT_BUILD_FUZZERS=ON
  "-DFREPKIT_SHARED_DIR=$shared_dir")
if [ -n "$launcher" ]; then
  configure+=("-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher" "-DCMAKE_C_COMPILER_LAUNCHER=$launcher")
fi
"${configure[@]}" > "$build_dir/configure.log" 2>&1 || { tail -30 "$build_dir/configure.log"; echo "sanitizer build: configure failed"; exit 1; }
echo "configured ($((SECONDS - started)) s)"

cmake --build "$tree" -j2 > "$build_dir/build.log" 2>&1 || { grep -E 'error|Error' "$build_dir/build.log" | head -30; echo "sanitizer build: build failed"; exit 1; }
echo "built ($((SECONDS - started)) s)"

# Every finding stops the process; leaks are reported at exit (LeakSanitizer).
export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
failures=0
# Not run sanitized: homotopic_demo (48 frames, sound and movie: 33 s in the release build, over
# its 600 s limit here); frepkit_map runs the same libraries on smaller mappings.
echo "not run under the sanitizers: homotopic_demo (too slow sanitized; frepkit_map covers its libraries)"
if ctest --test-dir "$tree" -j2 --output-on-failure -E '^homotopic_demo$' > "$build_dir/ctest.log" 2>&1; then
  echo "the sanitized test suite passed: $(grep -E 'tests passed' "$build_dir/ctest.log")"
else
  grep -E 'tests passed|\*\*\*Failed|\*\*\*Timeout|\*\*\*Exception|Failed  ' "$build_dir/ctest.log" | head -40
  echo "sanitizer build: the sanitized test suite failed (log: $build_dir/ctest.log)"
  failures=$((failures + 1))
fi
echo "tested ($((SECONDS - started)) s)"

# Two harnesses at a time: this test runs alone (RUN_SERIAL) on a machine of two cores or more.
if [ "$seconds" -gt 0 ]; then
  harnesses=(fuzz_hyperfun_parser fuzz_hyperfun_eval fuzz_vm_reader fuzz_mapping_plan fuzz_points_reader fuzz_hfp_arguments)
  running=0
  for h in "${harnesses[@]}"; do
    [ -x "$tree/bin/$h" ] || { echo "sanitizer build: harness $h was not built"; failures=$((failures + 1)); continue; }
    bash "$source_dir/Testing/Fuzz/run_fuzzer.sh" "$tree/bin/$h" libfuzzer "$source_dir" "$shared_dir" \
      "$build_dir/fuzz/$h" "$seconds" > "$build_dir/fuzz-$h.log" 2>&1 &
    running=$((running + 1))
    if [ "$running" -eq 2 ]; then
      wait
      running=0
    fi
  done
  wait
  for h in "${harnesses[@]}"; do
    echo "--- $h"
    cat "$build_dir/fuzz-$h.log" 2> /dev/null
    grep -qs "run_fuzzer: $h ok" "$build_dir/fuzz-$h.log" || failures=$((failures + 1))
  done
  echo "fuzzed ($((SECONDS - started)) s)"
fi
echo "sanitizer build: $failures failures"
[ "$failures" -eq 0 ]
