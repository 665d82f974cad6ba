# Shared by the frepkit test scripts (sourced): PASS/FAIL bookkeeping and running a command.
# The sourcing script sets $work (a scratch directory) and checks=0, failures=0.

pass() { checks=$((checks + 1)); echo "PASS: $1"; }
fail() { checks=$((checks + 1)); failures=$((failures + 1)); echo "FAIL: $1"; }

# run NAME EXPECTED_CODE CMD... : runs CMD, captures stdout/stderr in $out/$err, checks the code.
# A crash (exit code >= 128, e.g. SIGSEGV/SIGABRT) always fails.
run() {
  local name=$1 expected=$2
  shift 2
  "$@" >"$work/out" 2>"$work/err"
  code=$?
  out=$(cat "$work/out")
  err=$(cat "$work/err")
  if [ "$code" -ge 128 ]; then
    fail "$name: crashed with code $code; stderr: $err"
    return 1
  fi
  if [ "$code" -ne "$expected" ]; then
    fail "$name: exit code $code, expected $expected; stdout: $out; stderr: $err"
    return 1
  fi
  pass "$name"
}

expect_in() { # NAME HAYSTACK NEEDLE
  if [[ "$2" == *"$3"* ]]; then pass "$1"; else fail "$1: '$3' not in: $2"; fi
}
