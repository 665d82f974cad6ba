#!/usr/bin/env bash
# Runs one fuzz harness over its seed corpus (collect_seeds.sh).
# Usage: run_fuzzer.sh HARNESS_BINARY KIND SOURCE_DIR SHARED_DIR WORK_DIR SECONDS
#   KIND     libfuzzer (linked with -fsanitize=fuzzer) or replay (linked with replay_main.cpp)
#   SECONDS  0: run every seed and regression input once; > 0 (libfuzzer only): fuzz that long
#            from the seeds, then report executions and coverage.
# Fails on any crash, sanitizer report, oracle failure, timeout or out-of-memory; libFuzzer then
# leaves the input as WORK_DIR/crash-* (or leak-*, timeout-*, oom-*).
set -uo pipefail
binary=$1
kind=$2
source_dir=$3
shared_dir=$4
work=$5
seconds=$6
harness=$(basename "$binary")
fuzz_dir="$source_dir/Testing/Fuzz"
mkdir -p "$work"
bash "$fuzz_dir/collect_seeds.sh" "$harness" "$source_dir" "$shared_dir" "$work/seeds" || exit 1

if [ "$kind" = replay ]; then
  exec "$binary" "$work/seeds"
fi

# A fresh folder for what libFuzzer adds: the seeds stay as collected.
rm -rf "$work/corpus" && mkdir -p "$work/corpus"
options=(-timeout=30 -rss_limit_mb=2048 -print_final_stats=1 "-artifact_prefix=$work/")
case "$harness" in
  fuzz_hyperfun_*) dict="$fuzz_dir/hyperfun.dict" ;;
  fuzz_mapping_plan) dict="$fuzz_dir/mapping.dict" ;;
  fuzz_hfp_arguments) dict="$fuzz_dir/hfp.dict" ;;
  *) dict="" ;;
esac
[ -n "$dict" ] && options+=("-dict=$dict")
case "$harness" in
  fuzz_hyperfun_*|fuzz_mapping_plan) options+=(-max_len=4096) ;;
  *) options+=(-max_len=1024) ;;
esac
if [ "$seconds" -eq 0 ]; then
  options+=(-runs=0)
else
  options+=("-max_total_time=$seconds")
fi
"$binary" "${options[@]}" "$work/corpus" "$work/seeds" > "$work/fuzz.log" 2>&1
status=$?
# The figures of the run (libFuzzer's last status line and final stats).
grep -E '^#[0-9]+.*(DONE|INITED)|^stat::' "$work/fuzz.log" | tail -8
if [ "$status" -ne 0 ]; then
  tail -60 "$work/fuzz.log"
  ls "$work" | grep -E '^(crash|leak|timeout|oom|slow-unit)-' || true
  echo "run_fuzzer: $harness failed (exit $status)"
  exit 1
fi
echo "run_fuzzer: $harness ok"
