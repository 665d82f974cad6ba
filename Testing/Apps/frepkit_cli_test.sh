#!/usr/bin/env bash
# End-to-end checks of frepkit: every check prints PASS/FAIL; the script fails if any failed.
# A crash (exit code >= 128, e.g. SIGSEGV/SIGABRT) always fails.
#   frepkit_cli_test.sh FREPKIT SHARED_DIR SOURCE_DIR
set -u
frepkit=$1
shared=$2
source_dir=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0

source "$(dirname "$0")/test_helpers.sh"

model() { printf '%s' "$2" >"$work/$1"; echo "$work/$1"; }

sphere=$(model sphere.hf 'my_model(x[3], a[1]) { my_model = 5^2 - (x[1]^2 + x[2]^2 + x[3]^2); }')

# --- help and usage
run "help" 0 "$frepkit" --help
run "eval --help" 0 "$frepkit" eval --help
expect_in "eval help mentions --hfp-errors" "$out" "--hfp-errors"
run "check --help" 0 "$frepkit" check --help
run "no subcommand is a usage error" 1 "$frepkit"
run "unknown option is a usage error" 1 "$frepkit" eval "$sphere" --no-such-option

# --- check
run "check ok" 0 "$frepkit" check "$sphere"
expect_in "check lists the object" "$out" "my_model(x[3], a[1], s[1])"
expect_in "check: s[1] without s[] is the original's" "$out" "s[1] implicit, as in HyperFun: the header declares no s[]"
with_s=$(model with_s.hf 'my_model(x[3], a[1], s[2]) { s[2] = 1; my_model = 1; }')
run "check with s[2]" 0 "$frepkit" check "$with_s"
[[ "$out" == *"s[2])"* && "$out" != *"implicit"* ]] && pass "declared s[]: no note" || fail "declared s[]: $out"
run "check missing file" 1 "$frepkit" check "$work/none.hf"
expect_in "missing file message" "$err" "cannot open"
prog="$shared/hyperfun/models/web__paulbourke.net/HF_prog.hf"
run "check HF_prog" 0 "$frepkit" check "$prog"
expect_in "HF_prog lists csgobj" "$out" "csgobj(x[3], a[1], s[1])"

# --- eval values (exact %.17g)
run "eval sphere" 0 bash -c "printf '0 0 0\n1 2 3\n' | '$frepkit' eval '$sphere'"
expect_in "eval sphere value at origin" "$out" "25"
expect_in "eval sphere value at 1,2,3" "$out" "11"
[ "$(echo "$out" | wc -l)" -eq 2 ] && pass "one line per point" || fail "one line per point: $out"

run "eval points file and output file" 0 bash -c \
  "printf '0 0 0\n' >'$work/p.txt'; '$frepkit' eval '$sphere' --points '$work/p.txt' --output '$work/o.txt'"
[ "$(cat "$work/o.txt")" = "25" ] && pass "output file content" || fail "output file content"
ls "$work"/o.txt.tmp-* >/dev/null 2>&1 && fail "temporary output left behind" || pass "no temporary left"

# The original's values for an external model, through the compiled path and the interpreter.
tut="$shared/hyperfun/models/web__f-rep.org/tut_start_example1.hf"
tut_expected="$shared/hyperfun/models/web__f-rep.org/tut_start_example1.expected.txt"
awk '{print $1, $2, $3}' "$tut_expected" >"$work/tut_points"
awk '{print $4}' "$tut_expected" >"$work/tut_values"
run "eval tut_start_example1" 0 "$frepkit" eval "$tut" --points "$work/tut_points" --output "$work/tut_out"
if cmp -s "$work/tut_out" "$work/tut_values"; then pass "tut_start_example1 values equal the original's"; else fail "tut_start_example1 values differ"; fi
run "eval tut_start_example1 --interpreter" 0 "$frepkit" eval "$tut" --interpreter --points "$work/tut_points" --output "$work/tut_out2"
if cmp -s "$work/tut_out2" "$work/tut_values"; then pass "interpreter values equal the original's"; else fail "interpreter values differ"; fi

# object selection and parameters
run "eval object by name, case-insensitive" 0 bash -c "echo '0 0 0' | '$frepkit' eval '$prog' --object CSGobj"
run "eval unknown object" 1 bash -c "echo '0 0 0' | '$frepkit' eval '$prog' --object nosuch"
expect_in "unknown object lists objects" "$err" "csgobj"
expect_in "unknown object: the engine's message lists the objects" "$err" "no object named 'nosuch' (objects: "
for sub in "mesh -o $work/x.stl" "slice -o $work/x.csv --fix x3=0"; do
  run "$sub: unknown object" 1 $frepkit ${sub%% *} "$sphere" --object nosuch ${sub#* }
  expect_in "$sub: the same message" "$err" "no object named 'nosuch' (objects: my_model)"
done

# HyperFun library files (--library FILE.hf): the model calls their objects like its own.
homotopic="$source_dir/Examples/homotopic"
libs=(--library "$homotopic/cat.hf" --library "$homotopic/robot.hf" --library "$homotopic/nihon.hf" --library "$homotopic/roblet.hf")
printf '0.5 1 2 0.3 0.7\n-3 0.25 4 0.9 0.1\n0 0 0 0.5 0.5\n' >"$work/p5"
run "eval blend.hf with the key shapes as libraries" 0 "$frepkit" eval "$homotopic/blend.hf" "${libs[@]}" --points "$work/p5"
blend_values=$out
run "eval meta5d.hf (the same objects in one file)" 0 "$frepkit" eval "$homotopic/meta5d.hf" --points "$work/p5"
[ -n "$blend_values" ] && [ "$blend_values" = "$out" ] && pass "library objects: the same values as pasted" || fail "library values differ: $blend_values vs $out"
run "check blend.hf lists the library objects" 0 "$frepkit" check "$homotopic/blend.hf" "${libs[@]}"
expect_in "check: the default object is the file's own" "$out" "* my_model(x[5], a[1], s[1])"
run "blend.hf without its libraries" 1 "$frepkit" check "$homotopic/blend.hf"
run "a missing library file" 1 "$frepkit" check "$homotopic/blend.hf" --library "$work/none.hf"
expect_in "missing library: named" "$err" "$work/none.hf: cannot open the library file"
params=$(model params.hf 'my_model(x[1], a[2]) { my_model = a[1] * 10 + a[2] + x[1]; }')
run "eval -a" 0 bash -c "echo '0.5' | '$frepkit' eval '$params' -a 2,3"
[ "$out" = "23.5" ] && pass "parameters applied" || fail "parameters applied: $out"
run "eval missing parameters are 0" 0 bash -c "echo '0.5' | '$frepkit' eval '$params' -a 2"
[ "$out" = "20.5" ] && pass "missing parameter is 0" || fail "missing parameter is 0: $out"

# attributes
attr=$(model attr.hf 'my_model(x[1], a[1], s[2]) { s[1] = x[1] * 2; s[2] = 7; my_model = x[1]; }')
run "eval --attributes" 0 bash -c "echo '1.5' | '$frepkit' eval '$attr' --attributes"
[ "$out" = "1.5 3 7" ] && pass "attributes printed" || fail "attributes printed: $out"

# run-time errors: per point, with the original's message and position; --hfp-errors
div=$(model div.hf 'my_model(x[1], a[1])
{
  my_model = 1 / x[1];
}')
run "eval run-time error" 0 bash -c "printf '2\n0\n4\n' | '$frepkit' eval '$div'"
expect_in "error line" "$out" "error: $div:3:16: Division by zero"
expect_in "value after error" "$out" "0.25"
run "eval --hfp-errors" 0 bash -c "printf '2\n0\n4\n' | '$frepkit' eval '$div' --hfp-errors"
[ "$out" = "$(printf '0.5\n0.5\n0.25')" ] && pass "hfp-errors repeats the previous value" || fail "hfp-errors: $out"
run "eval --interpreter error" 0 bash -c "printf '0\n' | '$frepkit' eval '$div' --interpreter"
expect_in "interpreter error line" "$out" "Division by zero"

# --- one syntax for boxes and sizes: all minima then all maxima, or a range per axis by name
ball=$(model ball.hf 'my_model(x[3], a[1]) { my_model = 1 - (x[1]^2 + x[2]^2 + x[3]^2); }')
run "mesh --box numbers" 0 "$frepkit" mesh "$ball" -o "$work/box_numbers.stl" --box -1.5,-1.5,-1.5,1.5,1.5,1.5 --grid 16 -q
run "mesh --box by coordinate" 0 "$frepkit" mesh "$ball" -o "$work/box_names.stl" --box x1=-1.5:1.5,x2=-1.5:1.5,x3=-1.5:1.5 --grid 16 -q
run "mesh --box by axis, any order" 0 "$frepkit" mesh "$ball" -o "$work/box_axes.stl" --box z=-1.5:1.5,y=-1.5:1.5,x=-1.5:1.5 --grid 16 -q
cmp -s "$work/box_numbers.stl" "$work/box_names.stl" && pass "both box syntaxes: the same mesh" || fail "box syntaxes give different meshes"
cmp -s "$work/box_numbers.stl" "$work/box_axes.stl" && pass "axis names: the same mesh" || fail "axis names give a different mesh"
# slice: a section of a 4-D ball (a mesh, so that the VTK-free build runs it too), the named
# ranges in another order than the axes'.
ball4=$(model ball4.hf 'my_model(x[4], a[1]) { my_model = 1 - (x[1]^2 + x[2]^2 + x[3]^2 + x[4]^2); }')
run "slice --box by coordinate" 0 "$frepkit" slice "$ball4" -o "$work/box_names.stl" --fix x4=0 --box x3=-1.5:1.5,x1=-1.5:1.5,x2=-1.5:1.5 --grid 16 -q
run "slice --box numbers" 0 "$frepkit" slice "$ball4" -o "$work/box_numbers.stl" --fix x4=0 --box -1.5,-1.5,-1.5,1.5,1.5,1.5 --grid 16 -q
cmp -s "$work/box_numbers.stl" "$work/box_names.stl" && pass "slice: both box syntaxes the same" || fail "slice: box syntaxes differ"
bad_box() { # NAME BOX NEEDLE
  run "--box $1" 1 "$frepkit" mesh "$ball" -o "$work/bad_box.stl" --box "$2" -q
  expect_in "--box $1: message" "$err" "$3"
}
bad_box "VTK's order" -1.5,1.5,-1.5,1.5,-1.5,1.5 "ymin = 1.5 is not less than ymax = -1.5 (the numbers are xmin,ymin,zmin,xmax,ymax,zmax: all minima, then all maxima; or give ranges by name: x1=LO:HI,x2=LO:HI,x3=LO:HI)"
bad_box "missing axis" x1=-1:1,x2=-1:1 "--box: no range for x3 (axis z)"
bad_box "lo >= hi" x1=-1:1,x2=1:-1,x3=-1:1 "--box x2=1:-1: the minimum 1 is not less than the maximum -1"
bad_box "unknown name" x1=-1:1,q=0:1,x3=-1:1 "unknown axis 'q' (the box's axes are x1, x2, x3, also called x, y, z)"
bad_box "fixed coordinate" x1=-1:1,x4=0:1,x3=-1:1 "x4 is not a free coordinate"
bad_box "axis twice" x1=-1:1,x=0:1,x3=-1:1 "x1 is given twice"
bad_box "no range" x1=-1,x2=-1:1,x3=-1:1 "expected NAME=LO:HI"
bad_box "mixed" x1=-1:1,1,2 "not both"
bad_box "not a number" -1,-1,-1,1,1,one "'one' is not a number"
bad_box "wrong count" -1,-1,1,1 "--box needs 6 numbers"
if "$frepkit" render --help >/dev/null 2>&1; then
  run "render --size 64x48" 0 "$frepkit" render "$ball" -o "$work/size_x.png" --box -2,-2,-2,2,2,2 --size 64x48 -q
  run "render --size 64,48" 0 "$frepkit" render "$ball" -o "$work/size_comma.png" --box -2,-2,-2,2,2,2 --size 64,48 -q
  cmp -s "$work/size_x.png" "$work/size_comma.png" && pass "both size syntaxes: the same picture" || fail "size syntaxes give different pictures"
  run "render --size 64y48" 1 "$frepkit" render "$ball" -o "$work/size_bad.png" --size 64y48
  expect_in "bad --size message" "$err" "--size: expected WIDTHxHEIGHT or WIDTH,HEIGHT (e.g. 640x480 or 640,480)"
  run "render --size 0x48" 1 "$frepkit" render "$ball" -o "$work/size_bad.png" --size 0x48
fi

# --- bad input: clear message with a location, exit 1, never a crash
bad() { # NAME TEXT NEEDLE
  local f
  f=$(model "bad_$RANDOM.hf" "$2")
  run "bad model: $1" 1 "$frepkit" check "$f"
  expect_in "bad model: $1 names file:line:col" "$err" "$f:"
  [ -n "$3" ] && expect_in "bad model: $1 message" "$err" "$3"
}
bad "missing semicolon" 'my_model(x[3], a[1]) { my_model = 1 }' ""
bad "unknown function" 'my_model(x[3], a[1]) { my_model = hfNoSuch(x); }' ""
bad "wrong arity" 'my_model(x[3], a[1]) { array c[3]; c = [0,0,0]; my_model = hfSphere(x, c); }' ""
bad "unassigned name" 'my_model(x[3], a[1]) { my_model = q; }' "Unassigned"
bad "negative array size" 'my_model(x[3], a[1]) { array v[-3]; my_model = 1; }' ""
bad "huge array size" 'my_model(x[3], a[1]) { array v[1000000000000]; my_model = 1; }' ""
bad "huge x size" 'my_model(x[99999999999], a[1]) { my_model = 1; }' ""
bad "two errors reported" 'my_model(x[3], a[1]) { q = (1 + ; w = 2 * ; my_model = 1; }' ""
[ "$(grep -c 'error:' "$work/err")" -ge 2 ] && pass "several diagnostics reported" || fail "several diagnostics reported: $err"
empty=$(model empty.hf '')
run "empty file" 1 "$frepkit" eval "$empty"
expect_in "empty file message" "$err" "no object"
head -c 4096 /dev/urandom >"$work/garbage.hf"
run "binary garbage" 1 "$frepkit" check "$work/garbage.hf"
awk 'BEGIN { printf "my_model(x[3], a[1]) { my_model = "; for (i = 0; i < 100000; i++) printf "("; printf "1"; for (i = 0; i < 100000; i++) printf ")"; print "; }" }' >"$work/deep.hf"
run "deep nesting" 1 "$frepkit" check "$work/deep.hf"
expect_in "deep nesting message" "$err" "Nesting too deep"
run "points with text" 1 bash -c "printf '0 0 0\n1 abc 3\n' | '$frepkit' eval '$sphere'"
expect_in "points error names the line" "$err" "<stdin>:2:"
run "points with a wrong count" 1 bash -c "printf '0 0\n' | '$frepkit' eval '$sphere'"
expect_in "points count message" "$err" "expected 3 coordinates"
run "missing points file" 1 "$frepkit" eval "$sphere" --points "$work/nope.txt"
crlf=$(printf 'my_model(x[3], a[1])\r\n{\r\n  my_model = 1;\r\n}\r\n' >"$work/crlf.hf"; echo "$work/crlf.hf")
run "CRLF accepted" 0 bash -c "echo '0 0 0' | '$frepkit' eval '$crlf'"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
