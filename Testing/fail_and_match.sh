#!/usr/bin/env bash
# fail_and_match.sh REGEX COMMAND...: the mirror of run_and_match.sh, for checkers that must
# reject a bad case: passes only when COMMAND exits with 1 (a verdict, not a crash or a missing
# file: those exit otherwise) AND its output (lines joined by spaces) matches REGEX.
regex=$1
shift
out=$("$@" 2>&1)
code=$?
printf '%s\n' "$out"
if [ "$code" -ne 1 ]; then
  echo "fail_and_match: '$1' exited with $code, expected 1" >&2
  exit 1
fi
if ! printf '%s' "$out" | tr '\n' ' ' | grep -Eq -- "$regex"; then
  echo "fail_and_match: the output does not match: $regex" >&2
  exit 1
fi
