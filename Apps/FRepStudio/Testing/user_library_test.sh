#!/usr/bin/env bash
# FRepStudio --library: a model calling the example user library's ring() renders without
# errors in a screenshot; a library that does not exist is exit code 1 naming it. --shape: a
# model calling pebble(x), the example's STL, renders; a missing shape file is exit code 1.
#   user_library_test.sh XVFB_RUN FREPSTUDIO LIBRARY SOURCE_DIR
set -u
xvfb=$1
studio=$2
library=$3
model="$4/Examples/user-library/ring.hf"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
"$xvfb" "$studio" --library "$library" --screenshot "$work/ring.png" --size 640x400 "$model" \
  >"$work/out" 2>"$work/err"
code=$?
if [ $code -ne 0 ] || [ ! -s "$work/ring.png" ] || grep -q "model has errors" "$work/err"; then
  echo "FAIL: screenshot with the library: code $code, $(cat "$work/err")"; status=1
else
  echo "PASS: screenshot with the library"
fi
"$xvfb" "$studio" --library /nonexistent/libshapes.so --screenshot "$work/none.png" "$model" \
  >"$work/out" 2>"$work/err"
code=$?
if [ $code -ne 1 ] || ! grep -q "user library /nonexistent/libshapes.so: no such file" "$work/err"; then
  echo "FAIL: a missing library: code $code, $(cat "$work/err")"; status=1
else
  echo "PASS: a missing library is named, exit code 1"
fi
"$xvfb" "$studio" --screenshot "$work/without.png" --size 640x400 "$model" >"$work/out" 2>"$work/err"
if grep -q "model has errors" "$work/err"; then
  echo "PASS: without the library the model has errors"
else
  echo "FAIL: without the library no error was noted: $(cat "$work/err")"; status=1
fi
printf 'm(x[3], a[1])\n{\n  m = pebble(x);\n}\n' >"$work/pebble_call.hf"
"$xvfb" "$studio" --shape "pebble=$4/Examples/metamorphosis/pebble.stl" \
  --screenshot "$work/pebble.png" --size 640x400 "$work/pebble_call.hf" >"$work/out" 2>"$work/err"
code=$?
if [ $code -ne 0 ] || [ ! -s "$work/pebble.png" ] || grep -q "model has errors" "$work/err"; then
  echo "FAIL: screenshot with --shape: code $code, $(cat "$work/err")"; status=1
else
  echo "PASS: screenshot with --shape"
fi
"$xvfb" "$studio" --shape pebble=/nonexistent/pebble.stl --screenshot "$work/none.png" \
  "$work/pebble_call.hf" >"$work/out" 2>"$work/err"
code=$?
if [ $code -ne 1 ] || ! grep -q "shape pebble: /nonexistent/pebble.stl: cannot open" "$work/err"; then
  echo "FAIL: a missing shape file: code $code, $(cat "$work/err")"; status=1
else
  echo "PASS: a missing shape file is named, exit code 1"
fi
# HyperFun library files (--library FILE.hf, the engine's load_model): the Meta5D blend calling the
# four key shapes from their own files, and a .vm tape, load in FRepStudio as in frepkit.
homotopic="$4/Examples/homotopic"
"$xvfb" "$studio" --library "$homotopic/cat.hf" --library "$homotopic/robot.hf" \
  --library "$homotopic/nihon.hf" --library "$homotopic/roblet.hf" \
  --screenshot "$work/blend.png" --size 640x400 "$homotopic/blend.hf" >"$work/out" 2>"$work/err"
code=$?
if [ $code -ne 0 ] || [ ! -s "$work/blend.png" ] || grep -q "model has errors" "$work/err"; then
  echo "FAIL: blend.hf with HyperFun libraries: code $code, $(cat "$work/err")"; status=1
else
  echo "PASS: blend.hf with HyperFun libraries"
fi
"$xvfb" "$studio" --screenshot "$work/blend_alone.png" --size 640x400 "$homotopic/blend.hf" \
  >"$work/out" 2>"$work/err"
if grep -q "model has errors" "$work/err"; then
  echo "PASS: blend.hf without its libraries has errors"
else
  echo "FAIL: blend.hf without its libraries: no error noted: $(cat "$work/err")"; status=1
fi
exit $status
