#!/usr/bin/env bash
# frepkit --shape end to end: a mesh read from STL, OBJ, PLY (and .vtp with VTK) as a signed
# distance named in a model (meshed closed, with the STL's own volume), a volume (.vti, with
# VTK) as a field, bad shapes refused with exit code 1 naming the shape and what is wrong
# (open edges, missing file, bad spec, a library name), --unsigned-distance; and the example
# Examples/metamorphosis: the 4-D blend between the STL pebble (genus 0) and a torus (genus 1)
# as a spreadsheet and a short movie, and its two ends meshed with their genus checked.
#   frepkit_shapes_test.sh FREPKIT MESH_CHECK MEDIA_CHECK SOURCE_DIR vtk|novtk
set -u
frepkit=$(realpath "$1")
check=$(realpath "$2")
media=$([ "$3" = none ] && echo none || realpath "$3")
source_dir=$(realpath "$4")
vtk=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
source "$(dirname "$0")/test_helpers.sh"
field() { echo "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= t * m) }'; }
cd "$work" || exit 1

pebble="$source_dir/Examples/metamorphosis/pebble.stl"
stl_line=$("$check" "$pebble")
stl_volume=$(field volume "$stl_line")
cat > shape.hf <<'HF'
my_model(x[3], a[1]) { my_model = pebble(x); }
HF
box=-2.4,-2,-2,2.4,2,2.2
if run "mesh an STL shape" 0 "$frepkit" mesh --shape pebble="$pebble" shape.hf -o from_stl.stl \
  --box $box --grid 72 -q; then
  line=$("$check" from_stl.stl --closed)
  expect_in "STL shape meshed closed" "$?" "0"
  if near "$(field volume "$line")" "$stl_volume" 0.03; then pass "STL shape keeps the volume ($stl_volume)"
  else fail "STL shape volume $(field volume "$line") vs $stl_volume"; fi
  expect_in "STL shape is genus 0" "euler $(field euler "$line")" "euler 2"
fi

# The same pebble as OBJ and PLY (written by frepkit itself), read back as shapes.
"$frepkit" mesh "$source_dir/Examples/metamorphosis/pebble.hf" -o pebble.obj --grid 28 \
  --box -2.2,-1.6,-1.6,2,1.6,1.8 --no-normals -q
"$frepkit" mesh "$source_dir/Examples/metamorphosis/pebble.hf" -o pebble.ply --grid 28 \
  --box -2.2,-1.6,-1.6,2,1.6,1.8 --no-normals -q
for format in obj ply; do
  if run "mesh a .$format shape" 0 "$frepkit" mesh --shape pebble=pebble.$format shape.hf \
    -o from_$format.stl --box $box --grid 48 -q; then
    line=$("$check" from_$format.stl --closed)
    if near "$(field volume "$line")" "$stl_volume" 0.05; then pass ".$format shape volume"
    else fail ".$format shape volume $(field volume "$line") vs $stl_volume"; fi
  fi
done

printf '0 0 0\n5 0 0\n' > points.txt
if run "eval a shape" 0 "$frepkit" eval --shape pebble="$pebble" shape.hf -p points.txt; then
  inside=$(echo "$out" | sed -n 1p | awk '{ print $NF }')
  outside=$(echo "$out" | sed -n 2p | awk '{ print $NF }')
  expect_true() { if awk -v v="$2" "BEGIN { exit !($3) }"; then pass "$1"; else fail "$1: $2"; fi; }
  expect_true "inside is positive" "$inside" "v > 0.5"
  expect_true "outside is minus the distance" "$outside" "v < -2 && v > -4"
fi
run "slice a shape" 0 "$frepkit" slice --shape pebble="$pebble" shape.hf -o slice.vtp --fix x3=0 \
  --box -2.4,-2,2.4,2 --grid 64 -q

# Bad shapes.
printf 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n' > open.stl
run "an open mesh is refused" 1 "$frepkit" check --shape pebble=open.stl shape.hf
expect_in "open edges named" "$err" "--shape pebble: open.stl: the mesh is not closed and consistently oriented: 3 open edges"
run "unsigned distance accepts it" 0 "$frepkit" check --shape pebble=open.stl --unsigned-distance shape.hf
run "a missing shape file" 1 "$frepkit" check --shape pebble=nothing.stl shape.hf
expect_in "missing file named" "$err" "--shape pebble: nothing.stl: cannot open"
run "a bad spec" 1 "$frepkit" check --shape pebble.stl shape.hf
expect_in "bad spec explained" "$err" "expected name=FILE"
run "a library name" 1 "$frepkit" check --shape hfsphere="$pebble" shape.hf
expect_in "library name refused" "$err" "library function"
echo "garbage" > bad.stl
run "a malformed STL" 1 "$frepkit" check --shape pebble=bad.stl shape.hf
expect_in "malformed named" "$err" "bad.stl: not an STL file"
run "an unknown extension" 1 "$frepkit" check --shape pebble=shape.hf shape.hf
expect_in "extension named" "$err" "not a shape file"

if [ "$vtk" = vtk ]; then
  "$frepkit" mesh "$source_dir/Examples/metamorphosis/pebble.hf" -o pebble.vtp --grid 28 \
    --box -2.2,-1.6,-1.6,2,1.6,1.8 -q
  if run "mesh a .vtp shape" 0 "$frepkit" mesh --shape pebble=pebble.vtp shape.hf -o from_vtp.stl \
    --box $box --grid 48 -q; then
    line=$("$check" from_vtp.stl --closed)
    if near "$(field volume "$line")" "$stl_volume" 0.05; then pass ".vtp shape volume"
    else fail ".vtp shape volume $(field volume "$line") vs $stl_volume"; fi
  fi
  # A sampled volume: the pebble's F on a grid, read back as a field with iso 0.
  "$frepkit" slice "$source_dir/Examples/metamorphosis/pebble.hf" -o volume.vti --box $box \
    --grid 48 -q
  cat > ct.hf <<'HF'
my_model(x[3], a[1]) { my_model = ct(x); }
HF
  if run "mesh a .vti shape" 0 "$frepkit" mesh --shape ct=volume.vti:0 ct.hf -o from_vti.stl \
    --box $box --grid 48 -q; then
    line=$("$check" from_vti.stl --closed)
    if near "$(field volume "$line")" "$stl_volume" 0.05; then pass ".vti shape volume"
    else fail ".vti shape volume $(field volume "$line") vs $stl_volume"; fi
  fi
  run "a bad iso value" 1 "$frepkit" check --shape ct=volume.vti:abc ct.hf
  expect_in "iso named" "$err" "the iso value 'abc' is not a number"
else
  run ".vtp without VTK" 1 "$frepkit" check --shape pebble=pebble.vtp shape.hf
  expect_in "needs VTK" "$err" "need a frepkit built with VTK"
fi

# The example: the STL pebble (genus 0) turns into a torus (genus 1) along x4.
meta="$source_dir/Examples/metamorphosis"
for end in 0 1; do
  if run "metamorphosis at x4 = $end" 0 "$frepkit" slice --shape pebble="$pebble" \
    "$meta/metamorphosis.hf" --fix x4=$end -o end$end.stl --box -2.4,-2.4,-2.4,2.4,2.4,2.4 \
    --grid 64 -q; then
    line=$("$check" end$end.stl --closed)
    expected=$([ $end = 0 ] && echo 2 || echo 0)
    expect_in "x4 = $end has Euler characteristic $expected" "euler $(field euler "$line")" "euler $expected"
  fi
done
if run "metamorphosis map" 0 "$frepkit" map --shape pebble="$pebble" "$meta/metamorphosis.hf" \
  "$meta/metamorphosis.json" -O map --frames 6 --resolution 40 -q; then
  for f in map/spreadsheet.png map/metamorphosis.mp4 map/manifest.json map/frames/frame_00005.png; do
    if [ -s "$f" ]; then pass "$f written"; else fail "$f missing"; fi
  done
  if [ "$media" != none ]; then
    line=$("$media" movie map/metamorphosis.mp4)
    expect_in "movie has 6 frames" "frames $(field frames "$line")" "frames 6"
  fi
fi
# The frames' fingerprint covers the shape file: another mesh under the same name renders anew.
if [ -s map/frames/.fingerprint ] && [ -s from_stl.stl ]; then
  before=$(cat map/frames/.fingerprint)
  run "metamorphosis map with another pebble" 0 "$frepkit" map --shape pebble=from_stl.stl \
    "$meta/metamorphosis.hf" "$meta/metamorphosis.json" -O map --frames 6 --resolution 40 -q
  after=$(cat map/frames/.fingerprint)
  if [ "$before" != "$after" ]; then pass "another shape file changes the frames' fingerprint"
  else fail "the frames' fingerprint ignores the shape file ($before)"; fi
else
  fail "no fingerprint or no second mesh to compare"
fi
run "map without the shape fails clearly" 1 "$frepkit" map "$meta/metamorphosis.hf" \
  "$meta/metamorphosis.json" -O map2 -q
expect_in "unknown pebble" "$err" "pebble"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
