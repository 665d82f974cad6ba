#!/usr/bin/env bash
# End-to-end checks of frepkit mesh, hfp and slice: every format is written and read back (the
# checker verifies counts, that every edge is shared by two triangles run in opposite directions
# and that the volume is positive), hfp's documented examples, bad input. Every check prints
# PASS/FAIL; the script fails if any failed. A crash (exit code >= 128) always fails.
#   frepkit_mesh_test.sh FREPKIT MESH_CHECK SOURCE_DIR vtk|novtk
set -u
# Absolute paths: the checks run inside a scratch directory.
frepkit=$(realpath "$1")
check=$(realpath "$2")
source_dir=$(realpath "$3")
vtk=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
source "$(dirname "$0")/test_helpers.sh"
cd "$work" || exit 1

expect_true() { # NAME CONDITION-COMMAND...
  local name=$1
  shift
  if "$@"; then pass "$name"; else fail "$name"; fi
}
# near A B TOLERANCE: |A - B| <= TOLERANCE * |B|
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= t * m) }'; }
# field NAME LINE: the number after NAME in the checker's output line
field() { echo "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }
no_temporaries() { ! ls "$work"/*.tmp-* "$work"/*/*.tmp-* >/dev/null 2>&1; }

model() { printf '%s\n' "$2" >"$work/$1"; echo "$work/$1"; }

sphere=$(model sphere.hf 'my_model(x[3], a[1]) { my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2; }')
coloured=$(model coloured.hf 'my_model(x[3], a[1], s[3])
{
  s[1] = (x[1] + 5) / 10; s[2] = 0.5; s[3] = 1;
  my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2;
}')
# A 4-D sphere whose radius grows with x4: 2 at x4 = 0, 4 at x4 = 0.5.
anim=$(model anim.hf 'my_model(x[4], a[1]) { r = 2 + 4 * x[4]; my_model = r^2 - x[1]^2 - x[2]^2 - x[3]^2; }')
sphere_volume=523.599 # 4/3 pi 5^3

# --- mesh: every format, read back
run "mesh --help" 0 "$frepkit" mesh --help
expect_in "mesh help documents --grid" "$out" "--grid"
run "mesh to binary STL" 0 "$frepkit" mesh "$sphere" -o sphere.stl --grid 64
expect_in "mesh report has the triangle count" "$out" "triangles,"
expect_in "mesh report has the statistics" "$out" "culled; samples"
# No --box: the solid's own bounds (radius 5, plus 5% of its extent, rounded outwards).
expect_in "mesh says the box is the solid's bounds" "$err" "(the solid's bounds; --box to choose)"
expect_in "mesh report states the grid" "$out" "64 x 64 x 64 samples over [-5.6, 5.6] x [-5.6, 5.6] x [-5.6, 5.6]"
triangles=$(echo "$out" | sed -n 's/.*: \([0-9]*\) triangles,.*/\1/p' | head -1)
size=$(stat -c %s sphere.stl)
[ -n "$triangles" ] && [ "$size" -eq $((84 + 50 * triangles)) ] && pass "binary STL size is 84 + 50 n" || fail "binary STL size $size for $triangles triangles"
run "binary STL is closed and oriented" 0 "$check" sphere.stl --closed
expect_true "binary STL triangle count" [ "$(field triangles "$out")" = "$triangles" ]
expect_true "sphere volume within 2%" near "$(field volume "$out")" $sphere_volume 0.02

run "mesh with an explicit --box" 0 "$frepkit" mesh "$sphere" -o boxed.stl --grid 64 --box -10,-10,-10,10,10,10
expect_in "an explicit --box wins" "$out" "64 x 64 x 64 samples over [-10, 10] x [-10, 10] x [-10, 10]"
[ "${out#*solid\'s bounds}" = "$out" ] && pass "no bounds line with --box" || fail "bounds line with --box: $out"
halfspace=$(model half.hf 'my_model(x[3], a[1]) { my_model = 1 - x[3]; }')
run "mesh of a half-space" 0 "$frepkit" mesh "$halfspace" -o half.stl --grid 16
expect_in "a half-space is unbounded: warned, -10..10" "$err" "using -10..10 on each axis (choose with --box)"
expect_in "a half-space falls back to -10..10" "$out" "16 x 16 x 16 samples over [-10, 10] x [-10, 10] x [-10, 10]"
# A unit 4-D ball at x4 = 0 in its own box: thousands of triangles, not the few hundred of -10..10.
ball4=$(model ball4.hf 'my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2; }')
run "mesh of a unit 4-D ball" 0 "$frepkit" mesh "$ball4" -o ball4.stl
expect_true "a unit 4-D ball fills its own box" [ "$(echo "$out" | sed -n 's/.*: \([0-9]*\) triangles,.*/\1/p' | head -1)" -gt 10000 ]

run "mesh to ASCII STL" 0 "$frepkit" mesh "$sphere" -o ascii.stl --grid 64 --ascii -q
[ -z "$out" ] && pass "--quiet prints no report" || fail "--quiet printed: $out"
expect_true "ASCII STL starts with solid" [ "$(head -c 5 ascii.stl)" = "solid" ]
run "ASCII STL is closed and oriented" 0 "$check" ascii.stl --closed
expect_true "ASCII STL has the same triangles" [ "$(field triangles "$out")" = "$triangles" ]

for format in obj ply; do
  run "mesh to $format" 0 "$frepkit" mesh "$sphere" -o "sphere.$format" --grid 64 -q
  run "$format is closed and oriented" 0 "$check" "sphere.$format" --closed
  expect_true "$format has the same triangles" [ "$(field triangles "$out")" = "$triangles" ]
  expect_true "$format has normals" [ "$(field normals "$out")" = "yes" ]
  expect_true "$format has no colours for a model without s[]" [ "$(field colours "$out")" = "no" ]
done
points=$(field points "$out")
run "mesh --no-normals" 0 "$frepkit" mesh "$sphere" -o plain.ply --grid 64 -q --no-normals
run "PLY without normals" 0 "$check" plain.ply --closed
expect_true "--no-normals writes no normals" [ "$(field normals "$out")" = "no" ]

run "mesh to VRML" 0 "$frepkit" mesh "$sphere" -o sphere.wrl --grid 64 -q
expect_true "VRML header" [ "$(head -1 sphere.wrl)" = "#VRML V2.0 utf8" ]
expect_true "VRML has one coordIndex row per triangle" [ "$(grep -c -- ', -1,$' sphere.wrl)" = "$triangles" ]
expect_true "VRML without s[] has no colours" [ "$(grep -c colorPerVertex sphere.wrl)" = 0 ]
run "mesh a coloured model to VRML" 0 "$frepkit" mesh "$coloured" -o coloured.wrl --grid 64
expect_in "report says colours" "$out" "colours from s[1..3]"
expect_true "VRML has per-point colours" grep -q "colorPerVertex TRUE" coloured.wrl
colours=$(awk '/color Color/ { on = 1; next } on && /\]\}/ { on = 0 } on { n++ } END { print n }' coloured.wrl)
expect_true "VRML has one colour per point ($colours vs $points)" [ "$colours" = "$points" ]
run "mesh a coloured model to PLY" 0 "$frepkit" mesh "$coloured" -o coloured.ply --grid 32 -q
run "coloured PLY" 0 "$check" coloured.ply --closed
expect_true "PLY has colours" [ "$(field colours "$out")" = "yes" ]
run "mesh to POV-Ray" 0 "$frepkit" mesh "$sphere" -o sphere.pov --grid 32 -q
expect_true "POV has a mesh2" grep -q "^mesh2 {" sphere.pov
if [ "$vtk" = vtk ]; then
  run "mesh to VTK .vtp" 0 "$frepkit" mesh "$sphere" -o sphere.vtp --grid 64 -q
  expect_true "vtp is VTK XML PolyData with the triangles" grep -q "NumberOfPolys=\"$triangles\"" sphere.vtp
else
  run "mesh .vtp without VTK" 1 "$frepkit" mesh "$sphere" -o sphere.vtp
  expect_in ".vtp not available message" "$err" "not available in this build"
fi
expect_true "no temporary files left" no_temporaries

# --- mesh options
run "mesh --grid NX,NY,NZ and --box" 0 "$frepkit" mesh "$sphere" -o box.stl --grid 20,30,40 --box -6,-6,-6,6,6,6
expect_in "the grid is per axis" "$out" "20 x 30 x 40 samples over [-6, 6] x [-6, 6] x [-6, 6]"
run "mesh cut by the box is capped" 0 "$frepkit" mesh "$sphere" -o cut.stl --box -3,-3,-3,3,3,3 --grid 32 -q
run "capped mesh is closed" 0 "$check" cut.stl --closed
expect_true "capped volume is the box's (216)" near "$(field volume "$out")" 216 0.01
run "mesh --no-cap" 0 "$frepkit" mesh "$sphere" -o open.stl --box -3,-3,-3,3,3,3 --grid 32 -q --no-cap
run "uncapped mesh is read" 0 "$check" open.stl
expect_true "uncapped mesh is open where the box cuts it" [ "$(field boundary "$out")" -gt 0 ]
run "mesh --map (the former name of --axes) on a 4-D model" 0 "$frepkit" mesh "$anim" -o anim.stl --map X,Y,Z,0.5 --box -5,-5,-5,5,5,5 --grid 48 -q
run "4-D slice x4 = 0.5 is the sphere of radius 4" 0 "$check" anim.stl --closed
expect_true "x4 = 0.5 volume (268)" near "$(field volume "$out")" 268.08 0.03
run "mesh a 4-D model without --axes" 0 "$frepkit" mesh "$anim" -o anim0.stl --box -5,-5,-5,5,5,5 --grid 48
expect_in "note: x4 fixed at 0" "$err" "x4 is fixed at 0"
run "x4 = 0 is the sphere of radius 2" 0 "$check" anim0.stl --closed
expect_true "x4 = 0 volume (33.5)" near "$(field volume "$out")" 33.51 0.05
run "mesh --axes with Y and Z swapped" 0 "$frepkit" mesh "$anim" -o swapped.stl --axes X,Z,Y,0.5 --box -5,-5,-5,5,5,5 --grid 24 -q
run "swapped mapping still closed and outward" 0 "$check" swapped.stl --closed
run "mesh --iso" 0 "$frepkit" mesh "$sphere" -o iso.stl --iso 16 --grid 48 -q
run "iso 16 is the sphere of radius 3" 0 "$check" iso.stl --closed
expect_true "iso volume (113)" near "$(field volume "$out")" 113.1 0.03
params=$(model params.hf 'my_model(x[3], a[2]) { my_model = a[1]^2 - x[1]^2 - x[2]^2 - x[3]^2 + a[2]; }')
run "mesh -a" 0 "$frepkit" mesh "$params" -o params.stl -a 3,0 --grid 48 -q
run "a[1] = 3 is the sphere of radius 3" 0 "$check" params.stl --closed
expect_true "parameter volume (113)" near "$(field volume "$out")" 113.1 0.03
failing=$(model failing.hf 'my_model(x[3], a[1]) { my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2 + 0 * sqrt(x[1]); }')
run "run-time errors are counted, not silent" 0 "$frepkit" mesh "$failing" -o failing.stl --grid 32
expect_in "failed samples warning" "$err" "samples raised a run-time error"
count=$(echo "$out" | sed -n 's/.*failed samples \([0-9]*\).*/\1/p')
expect_true "failed samples reported as a count ($count)" [ "${count:-0}" -gt 0 ]
run "empty mesh: warning, exit 0" 0 "$frepkit" mesh "$sphere" -o empty.stl --box 20,20,20,30,30,30 --grid 8
expect_in "no surface warning" "$err" "no surface in the box"
expect_true "empty binary STL is valid (84 bytes)" [ "$(stat -c %s empty.stl)" = 84 ]
run "empty OBJ is valid" 0 "$frepkit" mesh "$sphere" -o empty.obj --box 20,20,20,30,30,30 --grid 8 -q

# --- mesh: bad input
run "missing model" 1 "$frepkit" mesh "$work/none.hf" -o x.stl
expect_in "missing model message" "$err" "cannot open"
bad=$(model bad.hf 'my_model(x[3], a[1])
{
  my_model = 1 +;
  q = ;
}')
run "parse error" 1 "$frepkit" mesh "$bad" -o x.stl
expect_in "parse error names file:line:col" "$err" "$bad:3:"
[ "$(grep -c 'error' "$work/err")" -ge 2 ] && pass "every diagnostic printed" || fail "every diagnostic printed: $err"
run "box with 3 numbers" 1 "$frepkit" mesh "$sphere" -o x.stl --box 1,2,3
expect_in "box count message" "$err" "--box needs 6 numbers"
run "box min >= max" 1 "$frepkit" mesh "$sphere" -o x.stl --box 0,0,0,1,0,1
expect_in "box order message" "$err" "is not less than"
run "grid 1" 1 "$frepkit" mesh "$sphere" -o x.stl --grid 1
expect_in "grid 1 message" "$err" "at least 2 samples"
start=$(date +%s%N)
run "grid 100000 is refused" 1 "$frepkit" mesh "$sphere" -o huge.stl --grid 100000
elapsed=$((($(date +%s%N) - start) / 1000000))
expect_in "the mesher's message" "$err" "samples is more than the limit"
expect_true "refused fast (${elapsed} ms)" [ "$elapsed" -lt 5000 ]
expect_true "no output file left" [ ! -e huge.stl ]
run "unwritable directory" 1 "$frepkit" mesh "$sphere" -o "$work/no/such/dir/x.stl" --grid 8
expect_in "unwritable message" "$err" "cannot write"
run "unknown extension" 1 "$frepkit" mesh "$sphere" -o x.3ds
expect_in "unknown extension lists the formats" "$err" ".stl"
run "2-D model" 1 "$frepkit" mesh "$(model flat.hf 'my_model(x[2], a[1]) { my_model = 1 - x[1]^2 - x[2]^2; }')" -o x.stl
expect_in "2-D model message" "$err" "needs 3 coordinates"
run "bad --axes" 1 "$frepkit" mesh "$anim" -o x.stl --axes X,Y,0.5
expect_in "bad --axes message" "$err" "--axes X,Y,0.5: Z is missing"
run "unknown object" 1 "$frepkit" mesh "$sphere" -o x.stl --object nosuch
expect_true "no temporary files left after errors" no_temporaries

# --- hfp: the documented examples
run "hfp example 1: -b 10 -g 100 -usedc 0 -stl" 0 "$frepkit" hfp "$sphere" -b 10 -g 100 -usedc 0 -stl model.stl
hfp_triangles=$(echo "$out" | sed -n 's/^triangles: //p')
expect_true "hfp prints the triangle count last" [ "$(echo "$out" | tail -1)" = "triangles: $hfp_triangles" ]
expect_true "-stl is ASCII" [ "$(head -c 5 model.stl)" = "solid" ]
run "hfp mesh is closed and oriented" 0 "$check" model.stl --closed
expect_true "hfp count equals the file's" [ "$(field triangles "$out")" = "$hfp_triangles" ]
run "hfp example 2: 4-D -x X,Y,Z,0.25 -g 60 -wrl" 0 "$frepkit" hfp "$anim" -usedc 0 -x X,Y,Z,0.25 -g 60 -wrl frame025.wrl
expect_true "frame025.wrl written" grep -q "IndexedFaceSet" frame025.wrl
run "hfp -x X,Y,Z,0.5 gives the x4 = 0.5 slice" 0 "$frepkit" hfp "$anim" -x X,Y,Z,0.5 -b 5 -g 48 -stlb slice.stl
run "hfp 4-D slice closed" 0 "$check" slice.stl --closed
expect_true "hfp slice volume (268)" near "$(field volume "$out")" 268.08 0.03
prog=$(model prog.hf 'block(x[3], a[1]) { block = (4 - x[1]^2) & (4 - x[2]^2) & (4 - x[3]^2); }
csgobj(x[3], a[2])
{
  array p[1];
  p[1] = 0;
  c = block(x, p);
  csgobj = c \ (a[1]^2 - (x[1] - a[2])^2 - x[2]^2 - x[3]^2);
}')
run "hfp example 3: -o csgobj -a 2.5,1 -b -5,-5,-5,5,5,5 -stlb" 0 "$frepkit" hfp "$prog" -o csgobj -a 2.5,1 -b -5,-5,-5,5,5,5 -stlb out.stl
hfp_triangles=$(echo "$out" | sed -n 's/^triangles: //p')
expect_true "-stlb is binary: 84 + 50 n bytes" [ "$(stat -c %s out.stl)" = $((84 + 50 * hfp_triangles)) ]
run "csgobj mesh closed" 0 "$check" out.stl --closed
csg_volume=$(field volume "$out")
run "hfp -o CSGobj (not lower case) falls back to the first object, as hfp" 0 "$frepkit" hfp "$prog" -o CSGobj -a 2.5,1 -b 5 -stlb fallback.stl
run "fallback mesh closed" 0 "$check" fallback.stl --closed
expect_true "the fallback is the block (volume 64)" near "$(field volume "$out")" 64 0.01
expect_true "csgobj is smaller than the block ($csg_volume)" awk -v v="$csg_volume" 'BEGIN { exit !(v > 1 && v < 60) }'
run "hfp example 4: -cli -gs 0.2" 0 "$frepkit" hfp "$sphere" -cli model.cli -gs 0.2
layers=$(echo "$out" | sed -n 's/^\([0-9]*\) layers have been successfully written$/\1/p')
expect_true "CLI header" [ "$(head -1 model.cli)" = '$$HEADERSTART' ]
expect_true "CLI has one \$\$LAYER per written layer ($layers)" [ "$(grep -c '^\$\$LAYER/' model.cli)" = "$layers" ]
expect_true "CLI ends with \$\$GEOMETRYEND" [ "$(tail -1 model.cli)" = '$$GEOMETRYEND' ]
expect_in "hfp prints minus the layers as triangles" "$out" "triangles: -$layers"
bad_polylines=$(awk -F'[/,]' '/^\$\$POLYLINE/ { n = $4; if (NF != 4 + 2 * n || $5 != $(NF - 1) || $6 != $NF) bad++ } END { print bad + 0 }' model.cli)
expect_true "every CLI polyline is closed with its point count" [ "$bad_polylines" = 0 ]
run "CLI of a shape cut by the box is closed along the box" 0 "$frepkit" hfp "$sphere" -cli cut.cli -b 3 -gs 0.5
expect_true "cut layers are outer (dir 1) squares of the box" grep -q '^\$\$POLYLINE/1,1,' cut.cli

# --- hfp: defaults, options, messages
run "hfp defaults" 0 "$frepkit" hfp "$sphere" -t
expect_in "-g 30 is 31 samples per axis (31^3 dense)" "$out" "of 2.979e+04 dense"
expect_in "-t reports times" "$out" "Time to Polygonize"
run "hfp writes default file names" 0 "$frepkit" hfp "$sphere" -wrl -stlb -pov -cf 255,0,0
expect_in "missing value message" "$out" "-wrl requires an argument."
expect_true "out.wrl, out.stl and out.pov" [ -s out.wrl ] && [ -s out.stl ] && [ -s out.pov ]
expect_true "-cf goes into diffuseColor" grep -q "diffuseColor 1 0 0" out.wrl
run "hfp -ct" 0 "$frepkit" hfp "$coloured" -ct -wrl ct.wrl
expect_true "-ct writes per-point colours" grep -q "colorPerVertex TRUE" ct.wrl
run "hfp -d 1 writes no normals" 0 "$frepkit" hfp "$sphere" -d 1 -wrl nonormals.wrl
expect_true "no Normal node" [ "$(grep -c normalPerVertex nonormals.wrl)" = 0 ]
run "hfp unknown token is ignored" 0 "$frepkit" hfp "$sphere" -zz -g 10
expect_in "ignored token message" "$out" "\"-zz\" is not a valid argument."
run "hfp viewer and engine options are accepted" 0 "$frepkit" hfp "$sphere" -g 10 -d 3 -cl 10 -w 300,200 -sb -sa -usedc 1 -s 0.05 -r
run "hfp no arguments" 1 "$frepkit" hfp
expect_in "no arguments message" "$err" "No arguments specified."
run "hfp no model first" 1 "$frepkit" hfp -g 50 "$sphere"
expect_in "no model message" "$err" "No Model specified."
run "hfp -h" 0 "$frepkit" hfp -h
expect_in "hfp usage" "$out" "Usage:"
run "hfp empty box" 1 "$frepkit" hfp "$sphere" -b 20,30 -stl empty_hfp.stl
expect_in "Isosurface not generated" "$err" "Isosurface not generated."
expect_in "triangles: 0" "$out" "triangles: 0"
run "hfp missing file" 1 "$frepkit" hfp "$work/none.hf"
expect_in "hfp missing file message" "$err" "not found"
run "hfp parse error" 1 "$frepkit" hfp "$bad" -stl x.stl
expect_in "hfp parse error names file:line:col" "$err" "$bad:3:"
run "hfp -g 1 is clamped to 2" 0 "$frepkit" hfp "$sphere" -g 1 -b 6
expect_in "clamp message" "$out" "Clamping to 2."
run "hfp unwritable output" 1 "$frepkit" hfp "$sphere" -stl "$work/no/such/dir/x.stl"
expect_true "no temporary files left after hfp" no_temporaries

# --- slice
h5="$source_dir/Examples/homotopy5d.hf"
run "slice --help" 0 "$frepkit" slice --help
if [ "$vtk" = vtk ]; then
  run "slice 2 free to PNG" 0 "$frepkit" slice "$h5" --fix x3=0,x4=0.5,x5=0.5 --box -5,-5,5,5 --grid 96,64 -o section.png
  expect_true "PNG signature" [ "$(head -c 8 section.png | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]
  expect_true "PNG is 96 x 64 (grid = image size)" [ "$(od -An -tu1 -j16 -N8 section.png | awk '{ print $3 * 256 + $4, $7 * 256 + $8 }')" = "96 64" ]
  expect_in "slice report" "$out" "96 x 64 image"
  run "slice 2 free to .vti" 0 "$frepkit" slice "$h5" --fix x3=0,x4=1,x5=0 -o section.vti --grid 32 -q
  expect_true ".vti is ImageData with F" grep -q 'Name="F"' section.vti
  run "slice 2 free to .vtp contour" 0 "$frepkit" slice "$h5" --fix x3=0,x4=1,x5=1 -o contour.vtp --box -5,-5,5,5
  expect_true ".vtp has lines" grep -q 'NumberOfLines="[1-9]' contour.vtp
  run "slice 3 free to a .vti volume" 0 "$frepkit" slice "$h5" --fix x4=0.5,x5=0.5 -o volume.vti --grid 16 -q
  run "a volume over the limit is refused" 1 "$frepkit" slice "$h5" --fix x4=0.5,x5=0.5 -o big.vti --grid 1000
  expect_in "volume limit message" "$err" "exceed the limit"
  run "slice --free order" 0 "$frepkit" slice "$h5" --fix x1=0,x4=1,x5=0 --free x3,x2 --box -5,-5,5,5 --grid 16 -o free.png -q
else
  run "slice .png without the stack" 1 "$frepkit" slice "$h5" --fix x3=0,x4=0.5,x5=0.5 -o section.png
  expect_in ".png not available message" "$err" "not available in this build"
  run "slice .vti without VTK" 1 "$frepkit" slice "$h5" --fix x3=0,x4=0.5,x5=0.5 -o section.vti
fi
run "slice 3 free to a mesh" 0 "$frepkit" slice "$h5" --fix x4=0,x5=0 --box -5,-5,-5,5,5,5 --grid 48 -o ball.stl -q
run "slice mesh closed" 0 "$check" ball.stl --closed
expect_true "x4 = x5 = 0 is the ball of radius 3 (113)" near "$(field volume "$out")" 113.1 0.03
run "slice 4 free" 1 "$frepkit" slice "$h5" --fix x4=0.5 -o x.png
expect_in "free count message" "$err" "4 free coordinates"
run "slice unplaced coordinate" 1 "$frepkit" slice "$h5" --fix x4=0,x5=0 --free x1,x2 -o x.png
expect_in "unplaced message" "$err" "x3 is neither fixed"
run "slice PNG with 3 free" 1 "$frepkit" slice "$h5" --fix x4=0,x5=0 -o x.png
run "slice unknown format" 1 "$frepkit" slice "$h5" --fix x3=0,x4=0,x5=0 -o x.gif
expect_in "slice formats listed" "$err" ".png"
expect_true "no temporary files left after slice" no_temporaries

# --- .vm tapes (the Prospero Challenge's format) wherever a .hf is read
vm="$source_dir/Examples/vm/two-discs.vm"
run "check a .vm tape" 0 "$frepkit" check "$vm"
expect_in ".vm is one 2-D object" "$out" "my_model(x[2], a[1], s[1])"
printf -- '-1 0\n0.25 0\n' > vm-points.txt
run "eval a .vm tape" 0 "$frepkit" eval "$vm" --points vm-points.txt
expect_in ".vm sign flipped: 1 inside at a disc's centre" "$out" "$(printf '1\n-0.25')"
if [ "$vtk" = vtk ]; then
  run "slice a .vm tape to a contour" 0 "$frepkit" slice "$vm" --box -3,-2,3,2 --grid 120,80 -o discs.vtp -q
  expect_true ".vm contour has lines" grep -q 'NumberOfLines="[1-9]' discs.vtp
fi
printf '_0 var-x\n_1 cube _0\n' > bad.vm
run "a bad .vm tape is refused" 1 "$frepkit" check bad.vm
expect_in ".vm error names file:line:col" "$err" "bad.vm:2:4: error: unknown opcode 'cube'"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
