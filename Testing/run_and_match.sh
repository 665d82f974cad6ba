#!/usr/bin/env bash
# run_and_match.sh REGEX COMMAND...: runs COMMAND, shows its output, and passes only when it
# exits with 0 AND its output (lines joined by spaces) matches the extended regular expression.
# ctest's PASS_REGULAR_EXPRESSION alone ignores the exit code: a program that printed the
# expected lines and then crashed would pass.
regex=$1
shift
out=$("$@" 2>&1)
code=$?
printf '%s\n' "$out"
if [ "$code" -ne 0 ]; then
  echo "run_and_match: '$1' exited with $code" >&2
  exit 1
fi
if ! printf '%s' "$out" | tr '\n' ' ' | grep -Eq -- "$regex"; then
  echo "run_and_match: the output does not match: $regex" >&2
  exit 1
fi
