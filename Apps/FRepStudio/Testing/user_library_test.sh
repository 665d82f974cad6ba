#!/usr/bin/env bash
# FRepStudio --library: a model calling the example user library's ring() renders without
# errors in a screenshot; a library that does not exist is exit code 1 naming it. --shape: a
# model calling pebble(x), the example's STL, renders; a missing shape file is exit code 1.
# HyperFun library files: the Meta5D blend calling the four key shapes from their own files.
#   user_library_test.sh XVFB_RUN FREPSTUDIO LIBRARY SOURCE_DIR
set -u
xvfb=$1
studio=$2
library=$3
model="$4/Examples/user-library/ring.hf"
homotopic="$4/Examples/homotopic"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0

# studio ARGS...: FRepStudio under Xvfb, its output in $work/out and $work/err, its code in $code.
studio() {
  "$xvfb" "$studio" "$@" >"$work/out" 2>"$work/err"
  code=$?
}
pass() { echo "PASS: $1"; }
fail() { echo "FAIL: $1: code $code, $(cat "$work/err")"; status=1; }

# renders LABEL PNG ARGS...: exit 0, a picture written, no model error noted.
renders() {
  local label=$1 png=$2
  shift 2
  studio --screenshot "$png" --size 640x400 "$@"
  if [ $code -ne 0 ] || [ ! -s "$png" ] || grep -q "model has errors" "$work/err"; then
    fail "$label"
  else
    pass "$label"
  fi
}
# has_errors LABEL ARGS...: the screenshot notes that the model has errors.
has_errors() {
  local label=$1
  shift
  studio --screenshot "$work/errors.png" --size 640x400 "$@"
  if grep -q "model has errors" "$work/err"; then pass "$label"; else fail "$label"; fi
}
# refuses LABEL MESSAGE ARGS...: exit 1 with MESSAGE on stderr.
refuses() {
  local label=$1 message=$2
  shift 2
  studio --screenshot "$work/none.png" "$@"
  if [ $code -ne 1 ] || ! grep -q "$message" "$work/err"; then fail "$label"; else pass "$label"; fi
}

renders "screenshot with the library" "$work/ring.png" --library "$library" "$model"
refuses "a missing library is named, exit code 1" \
  "user library /nonexistent/libshapes.so: no such file" --library /nonexistent/libshapes.so "$model"
has_errors "without the library the model has errors" "$model"

printf 'm(x[3], a[1])\n{\n  m = pebble(x);\n}\n' >"$work/pebble_call.hf"
renders "screenshot with --shape" "$work/pebble.png" \
  --shape "pebble=$4/Examples/metamorphosis/pebble.stl" "$work/pebble_call.hf"
refuses "a missing shape file is named, exit code 1" \
  "shape pebble: /nonexistent/pebble.stl: cannot open" \
  --shape pebble=/nonexistent/pebble.stl "$work/pebble_call.hf"

# HyperFun library files (--library FILE.hf, the engine's load_model) load in FRepStudio as in
# frepkit.
renders "blend.hf with HyperFun libraries" "$work/blend.png" \
  --library "$homotopic/cat.hf" --library "$homotopic/robot.hf" \
  --library "$homotopic/nihon.hf" --library "$homotopic/roblet.hf" "$homotopic/blend.hf"
has_errors "blend.hf without its libraries has errors" "$homotopic/blend.hf"
exit $status
