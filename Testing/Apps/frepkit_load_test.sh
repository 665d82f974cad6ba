#!/usr/bin/env bash
# Big requests under a memory limit (ulimit -v, the address space): each is refused with a
# message and exit code 1 and nothing written, or finishes within the limit. Never a crash, an
# "internal error" or a left temporary (issue 18, item 6).
#   frepkit_load_test.sh FREPKIT SOURCE_DIR
# The limits sit above what frepkit needs to start (the PNG module pulls OpenImageIO's ~250
# libraries: about 400 MB of address space) and far below what the big requests would take.
set -u
frepkit=$(realpath "$1")
source_dir=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
checks=0
failures=0
source "$(dirname "$0")/test_helpers.sh"
cd "$work" || exit 1
limited() { # KB CMD...: the command under ulimit -v KB (in a subshell: the limit stays there)
  local kb=$1
  shift
  (ulimit -v "$kb" && exec "$@")
}
no_temporaries() { # NAME DIR
  local left
  left=$(find "$2" -name '*.tmp-*' 2>/dev/null)
  if [ -z "$left" ]; then pass "$1: no temporaries"; else fail "$1: temporaries left: $left"; fi
}
model="$source_dir/Examples/mapping/morph4d.hf"
robot="$source_dir/Examples/homotopic/robot.hf"

# 1. frepkit map of a 2,000-frame animation (80 s at 25 fps, small pictures): finishes within
# 700 MB with every frame and the whole sound (the movie, 26 s more of ffmpeg, is left out).
cat >frames2000.json <<'JSON'
{ "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2.4, 2.4] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2.4, 2.4] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2.4, 2.4] }],
    "x4": [{ "type": "dynamic", "range": [0, 1] },
           { "type": "audio", "parameter": "pitch", "range": [0, 1], "target": [262, 523] }] },
  "animation": { "duration": 80, "fps": 25 },
  "world": { "resolution": 8 },
  "render": { "width": 32, "height": 24 } }
JSON
run "map, 2000 frames under 700 MB" 0 limited 700000 \
  "$frepkit" map "$model" frames2000.json -O anim -j 2 -q --only frames,audio
frames=$(find anim/frames -name 'frame_*.png' | wc -l)
expect_in "map: 2000 frames written" "$frames" "2000"
python3 -c "import json,sys; m=json.load(open('anim/manifest.json')); sys.exit(0 if any(f.get('count') == 2000 for f in m['files']) else 1)" &&
  pass "map: the manifest lists 2000 frames" || fail "map: the manifest does not list 2000 frames"
no_temporaries "map, 2000 frames" anim

# 2. An animation too long to plan (10^6 s at 25 fps): refused before anything is allocated.
sed 's/"duration": 80/"duration": 1000000/' frames2000.json >frames_huge.json
run "map, 25 million frames under 700 MB" 1 limited 700000 \
  "$frepkit" map "$model" frames_huge.json -O huge -j 2 -q
expect_in "map, 25 million frames: refused" "$err" "frames (duration x fps)"
if [ ! -e huge ]; then pass "map, 25 million frames: nothing written"; else fail "map: huge/ written"; fi

# 3. Meshes of 4095^3 cells (4096^3 samples, the engine's limit; hfp's -g 4095). A small
# sphere finishes within 450 MB (the culling skips the empty boxes; the mesher's per-slab
# buffers take ~340 MB at this size); the Robot's surface does not fit: refused when the memory
# runs out, the old output kept and no temporary left.
printf 'tiny(x[3], a[1])\n{\n  tiny = 0.01^2 - (x[1]-0.3)^2 - (x[2]-0.2)^2 - (x[3]-0.1)^2;\n}\n' >tiny.hf
run "hfp -g 4095, small sphere under 450 MB" 0 limited 450000 "$frepkit" hfp tiny.hf -g 4095 -stl tiny.stl
if [ -s tiny.stl ]; then pass "small sphere: STL written"; else fail "small sphere: no STL"; fi
echo "old" >robot.stl
run "hfp -g 4095, Robot under 400 MB" 1 limited 400000 "$frepkit" hfp "$robot" -g 4095 -stl robot.stl
expect_in "Robot: out of memory, said so" "$err" "out of memory"
expect_in "Robot: the old STL kept" "$(cat robot.stl)" "old"
no_temporaries "Robot" .
# One sample more per axis than the limit: refused before allocating, at once.
run "mesh --grid 4097 under 400 MB" 1 limited 400000 "$frepkit" mesh "$robot" --grid 4097 -o big.stl -q
expect_in "mesh --grid 4097: refused by the limit" "$err" "is more than the limit"
if [ ! -e big.stl ]; then pass "mesh --grid 4097: nothing written"; else fail "big.stl written"; fi

echo "$checks checks, $failures failures"
[ "$failures" -eq 0 ]
