#!/usr/bin/env bash
# The main job end to end at the demo's own settings (ray-cast cells, meshed floor-scene frames at 128^3),
# with 48 frames instead of 240 to keep the suite short: every output exists; the spreadsheet
# has 25 non-empty cells and matches its baseline picture; the movie has the announced frame
# count and an audio stream of the same duration; the ghost is listed at the resolution asked;
# the topology map covers every cell and frame; the key shapes' STL files are closed
# meshes; the manifest lists everything and names the model drawn (meta5d.hf in the output folder,
# written from the key files by the metamorphosis component, keys aligned by size), whose corners
# are the key files' objects exactly. Without VTK, --normalise distance is refused (its files are .vti).
#   homotopic_demo_test.sh FREPKIT MEDIA_CHECK IMAGE_CHECK MESH_CHECK SPREADSHEET_BASELINE FRAME_BASELINE vtk|novtk
set -u
frepkit=$(realpath "$1")
media=$(realpath "$2")
image=$(realpath "$3")
mesh=$(realpath "$4")
baseline=$(realpath "$5")
frame_baseline=$(realpath "$6")
vtk=$7
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
source "$(dirname "$0")/../Apps/test_helpers.sh"
cd "$work" || exit 1
field() { echo "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= t * m) }'; }

run "demo runs" 0 "$frepkit" demo homotopic -O demo --frames 48 --ghost 24 --topology 32
echo "$err"
for f in meta5d.hf spreadsheet.png spreadsheet-topology.png topology.png path.png ghost.png homotopic.mp4 homotopic.wav manifest.json cat.stl robot.stl nihon.stl roblet.stl frames/frame_00047.png; do
  if [ -s "demo/$f" ]; then pass "demo/$f written"; else fail "demo/$f missing"; fi
done

line=$("$image" cells demo/spreadsheet.png demo/manifest.json)
echo "spreadsheet: $line"
expect_in "25 cells" "$line" "cells 25 nonempty 25"
line=$("$image" compare demo/spreadsheet.png "$baseline")
echo "against the baseline: $line"
if awk -v d="$(field differing_fraction "$line")" -v m="$(field mean_difference "$line")" 'BEGIN { exit !(d < 0.002 && m < 0.003) }'; then
  pass "spreadsheet matches its baseline"
else
  kept="${TMPDIR:-/tmp}/homotopic_spreadsheet.failed.png"
  cp demo/spreadsheet.png "$kept" 2>/dev/null
  fail "spreadsheet differs from its baseline ($line); the picture is kept as $kept"
fi

line=$("$image" compare demo/frames/frame_00020.png "$frame_baseline")
echo "frame 20 against its baseline: $line"
if awk -v d="$(field differing_fraction "$line")" -v m="$(field mean_difference "$line")" 'BEGIN { exit !(d < 0.002 && m < 0.003) }'; then
  pass "frame 20 (the shape on the floor, the path, the caption) matches its baseline"
else
  kept="${TMPDIR:-/tmp}/homotopic_frame_20.failed.png"
  cp demo/frames/frame_00020.png "$kept" 2>/dev/null
  fail "frame 20 differs from its baseline ($line); the picture is kept as $kept"
fi

line=$("$media" movie demo/homotopic.mp4)
echo "movie: $line"
expect_in "48 frames" "frames $(field frames "$line")" "frames 48"
if near "$(field duration "$line")" 2.0 0.05; then pass "movie lasts 48 / 24 s"; else fail "movie duration: $line"; fi
expect_in "1280x720" "$(field width "$line")x$(field height "$line")" "1280x720"
expect_in "movie has audio" "$(field audio "$line")" "1"
if near "$(field audio_duration "$line")" "$(field duration "$line")" 0.05; then pass "audio as long as the video"; else fail "audio duration: $line"; fi

for shape in cat robot nihon roblet; do
  line=$("$mesh" "demo/$shape.stl" 2>&1)
  if [[ "$line" == *"boundary 0 nonmanifold 0 misoriented 0 degenerate 0"* ]]; then pass "$shape.stl closed and oriented"; else fail "$shape.stl: $line"; fi
done

count=$(/usr/bin/python3 -c "import json; m = json.load(open('demo/manifest.json')); print(len(m['files']))")
expect_in "manifest lists 7 pictures/sounds/movies + 4 meshes" "files $count" "files 12"
# The map of the topology at the resolution asked: every cell, every frame, the changes located.
line=$(/usr/bin/python3 -c "import json; t = json.load(open('demo/manifest.json'))['topology']; s, f = t['spreadsheet'], t['frames']; print('resolution', t['resolution'], 'cells', len(s['cells']), 'frames', len(f['pieces']), len(f['genus']), 'located', all(0 <= c['between'][0] < c['between'][1] <= 1 for c in s['changes']) and all(c['frames'][1] - c['frames'][0] <= 0.5 + 1e-9 for c in f['changes']))")
expect_in "manifest maps the topology" "$line" "resolution 32 cells 25 frames 48 48 located True"
# The ghost (Meta5D projected along its path) at the resolution asked, a mesh with triangles.
line=$(/usr/bin/python3 -c "import json; g = [f for f in json.load(open('demo/manifest.json'))['files'] if f['kind'] == 'ghost'][0]; print('resolution', g['resolution'], 'tolerance', g['tolerance'], 'coordinates', ','.join(g['coordinates']), 'meshed', g['triangles'] > 1000)")
expect_in "manifest lists the ghost" "$line" "resolution 24 tolerance 0.001 coordinates x4,x5 meshed True"

line=$(/usr/bin/python3 -c "import json; m = json.load(open('demo/manifest.json')); print('model', m['model'], 'object', m['object'], 'alignment', m['morph']['alignment'], 'keys', len(m['morph']['keys']))")
expect_in "manifest names the model drawn" "$line" "model meta5d.hf object meta5d alignment size keys 4"
examples=$(dirname "$frepkit")/../share/frepkit/examples/homotopic
points="0.5 1 -2
-3 2.5 4
1.25 -0.75 0.3"
for key in "cat 0 0" "robot 1 0" "nihon 0 1" "roblet 1 1"; do
  set -- $key
  blend=$(echo "$points" | awk -v a="$2" -v b="$3" '{ print $0, a, b }' | "$frepkit" eval demo/meta5d.hf -o meta5d)
  own=$(echo "$points" | "$frepkit" eval "$examples/$1.hf" -o "$1")
  if [ -n "$own" ] && [ "$blend" == "$own" ]; then pass "meta5d.hf at ($2, $3) is $1.hf exactly"; else fail "meta5d.hf at ($2, $3): '$blend' vs $1.hf '$own'"; fi
done

# Normalised by distance (small and meshed, to stay quick): the keys' distance volumes are
# written beside meta5d.hf and named in the manifest; with them meta5d.hf loads again and its
# corners are inside exactly where the keys are.
if [ "$vtk" = novtk ]; then
  run "demo --normalise distance without VTK" 1 "$frepkit" demo homotopic -O nd --frames 2 \
    --resolution 16 --mesh-grid 16 --method mesh --normalise distance --ghost 0 -q
  expect_in "needs VTK" "$err" "--normalise distance needs a frepkit built with VTK"
else
  run "demo --normalise distance" 0 "$frepkit" demo homotopic -O nd --frames 2 --resolution 16 \
    --mesh-grid 16 --method mesh --normalise distance --ghost 0 -q
  if [ ! -e nd/ghost.png ]; then pass "--ghost 0: no ghost"; else fail "--ghost 0 drew a ghost"; fi
  shapes=$(/usr/bin/python3 -c "import json; m = json.load(open('nd/manifest.json'))['morph']; print(m['normalisation'], ' '.join('--shape %s=nd/%s' % kv for kv in sorted(m['shapes'].items())))")
  expect_in "manifest names the distances" "$shapes" "distance --shape mdist_cat=nd/meta5d-cat-distance.vti"
  for key in "cat 0 0" "roblet 1 1"; do
    set -- $key
    awk 'BEGIN { srand(7); for (i = 0; i < 200; i++) print -9 + 18 * rand(), -9 + 18 * rand(), -9 + 18 * rand() }' > p3.txt
    blend=$(awk -v a="$2" -v b="$3" '{ print $0, a, b }' p3.txt | "$frepkit" eval nd/meta5d.hf -o meta5d ${shapes#distance } | awk '{ print ($1 >= 0) }')
    own=$("$frepkit" eval "$examples/$1.hf" -o "$1" -p p3.txt | awk '{ print ($1 >= 0) }')
    if [ "$(echo "$blend" | wc -l)" -eq 200 ] && [ "$blend" == "$own" ]; then pass "normalised meta5d.hf at ($2, $3) is inside where $1.hf is"; else fail "normalised meta5d.hf at ($2, $3): sides differ from $1.hf"; fi
  done
fi

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
