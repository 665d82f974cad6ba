#!/usr/bin/env bash
# End-to-end checks of frepkit map: a 4-D ball whose radius is x4, mapped with x1..x3 world, x4
# on the spreadsheet's columns, and x4 dynamic with its pitch and loudness as sound. Checks the
# files, their sizes, the sound's length, pitch and loudness, the movie's frames and audio
# stream, the manifest, resuming an interrupted run, and that bad mapping files are refused with
# the place named and nothing written. Every check prints PASS/FAIL; a crash always fails.
#   frepkit_map_test.sh FREPKIT MEDIA_CHECK SOURCE_DIR
set -u
frepkit=$(realpath "$1")
media=$(realpath "$2")
source_dir=$(realpath "$3")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
source "$(dirname "$0")/test_helpers.sh"
cd "$work" || exit 1
py=/usr/bin/python3

near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= t * m) }'; }
field() { echo "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }
json() { "$py" -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$1" "$2"; }
png_size() { "$py" -c "import struct,sys; b=open(sys.argv[1],'rb').read(24); print(*struct.unpack('>II', b[16:24]))" "$1"; }

printf '%s\n' 'my_model(x[4], a[1]) { my_model = x[4] * x[4] - x[1] * x[1] - x[2] * x[2] - x[3] * x[3]; }' >ball.hf

cat >ball.json <<'JSON'
{
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "values": [0.5, 1, 1.5] },
           { "type": "dynamic", "range": [0.5, 1.5] },
           { "type": "audio", "parameter": "pitch", "range": [0.5, 1.5], "target": [220, 440] },
           { "type": "audio", "parameter": "loudness", "range": [0.5, 1.5], "target": [0.2, 0.8] },
           { "type": "colour", "colormap": "plasma", "range": [0.5, 1.5] }]
  },
  "animation": { "duration": 2, "fps": 6 },
  "world": { "resolution": 40 },
  "spreadsheet": { "cell_size": 160, "spacing": 0.1 },
  "render": { "width": 320, "height": 180 }
}
JSON

run "map runs" 0 "$frepkit" map ball.hf ball.json -O result
expect_in "summary names the stages" "$err" "spreadsheet"
expect_in "summary has the total" "$err" "total"
for f in spreadsheet.png ball.wav ball.mp4 manifest.json frames/frame_00000.png frames/frame_00011.png; do
  if [ -s "result/$f" ]; then pass "out/$f written"; else fail "out/$f missing"; fi
done
if [ ! -e result/frames/frame_00012.png ]; then pass "12 frames, no more"; else fail "a 13th frame"; fi
if [ ! -e result/path.png ]; then pass "no path picture with one dynamic coordinate"; else fail "path.png with one dynamic coordinate"; fi
if ls result/*.partial* result/*.tmp-* result/frames/*.tmp-* >/dev/null 2>&1; then fail "temporary files left"; else pass "no temporary files"; fi
read -r w h < <(png_size result/frames/frame_00003.png)
if [ "$w" = 320 ] && [ "$h" = 180 ]; then pass "frame size 320x180"; else fail "frame size ${w}x${h}"; fi
read -r w h < <(png_size result/spreadsheet.png)
if [ "$w" -gt $((3 * 160)) ] && [ "$h" -gt 160 ] && [ "$h" -lt $((2 * 160 + 160)) ]; then pass "spreadsheet 3 cells wide, one row (${w}x${h})"; else fail "spreadsheet size ${w}x${h}"; fi

# The manifest lists every file and each frame's values.
expect_in "manifest: 12 frames" "$(json result/manifest.json "[f['count'] for f in d['files'] if f['kind']=='frames'][0]")" "12"
expect_in "manifest: 3 cells" "$(json result/manifest.json "len([f for f in d['files'] if f['kind']=='spreadsheet'][0]['cells'])")" "3"
x4_last=$(json result/manifest.json "[f for f in d['files'] if f['kind']=='frames'][0]['frames'][11]['values']['x4']")
if near "$x4_last" 1.41666666 1e-6; then pass "frame 11 at x4 = 0.5 + 11/12"; else fail "frame 11 at x4 = $x4_last"; fi
expect_in "manifest: the cells' labels" "$(json result/manifest.json "[f for f in d['files'] if f['kind']=='spreadsheet'][0]['cells'][2]['label']")" "x4 = 1.5"

# The sound: 2 s at 44100 Hz, pitch from ~220 to ~440 Hz (x4 from 0.5 to 1.5 - 1/6), louder at the end.
line=$("$media" wav result/ball.wav 0.1)
echo "wav: $line"
if near "$(field duration "$line")" 2.0 1e-6; then pass "wav lasts 2 s"; else fail "wav duration: $line"; fi
expect_in "wav rate" "$(field rate "$line")" "44100"
if near "$(field pitch_start "$line")" 220 0.03; then pass "pitch starts near 220 Hz"; else fail "pitch start: $line"; fi
# the last frame (x4 = 1.4167) holds 220 + 220 * 0.9167 = 421.7 Hz
if near "$(field pitch_end "$line")" 421.7 0.03; then pass "pitch ends near 422 Hz"; else fail "pitch end: $line"; fi
if awk -v a="$(field rms_start "$line")" -v b="$(field rms_end "$line")" 'BEGIN { exit !(b > 2.5 * a) }'; then pass "louder at the end"; else fail "loudness: $line"; fi
if awk -v p="$(field peak "$line")" 'BEGIN { exit !(p <= 1.0 && p > 0.1) }'; then pass "peak within [0.1, 1]"; else fail "peak: $line"; fi

# The movie: 12 frames at 6 fps = 2 s, with an audio stream of the same length.
line=$("$media" movie result/ball.mp4)
echo "movie: $line"
expect_in "movie has 12 frames" "frames $(field frames "$line")" "frames 12"
if near "$(field duration "$line")" 2.0 0.09; then pass "movie lasts 2 s"; else fail "movie duration: $line"; fi
expect_in "movie has audio" "$(field audio "$line")" "1"
if near "$(field audio_duration "$line")" 2.0 0.09; then pass "audio lasts 2 s"; else fail "audio duration: $line"; fi

# Resuming: a second run keeps the frames; a changed mapping renders them again.
run "second run" 0 "$frepkit" map ball.hf ball.json -O result
expect_in "second run keeps the frames" "$err" "12 kept from an earlier run"
rm result/frames/frame_00004.png
run "resume after a lost frame" 0 "$frepkit" map ball.hf ball.json -O result
expect_in "resume renders only the lost frame" "$err" "11 kept from an earlier run"
if [ -s result/frames/frame_00004.png ]; then pass "lost frame rendered again"; else fail "lost frame missing"; fi
sed 's/"plasma"/"viridis"/' ball.json >ball2.json
cp ball2.json ball.json
run "changed mapping" 0 "$frepkit" map ball.hf ball.json -O result
if [[ "$err" != *"kept from an earlier run"* ]]; then pass "changed mapping renders every frame"; else fail "stale frames kept: $err"; fi
run "--force" 0 "$frepkit" map ball.hf ball.json -O result --force --only frames
if [[ "$err" != *"kept from an earlier run"* ]]; then pass "--force renders every frame"; else fail "--force kept frames"; fi

# --only and overrides.
run "--only spreadsheet" 0 "$frepkit" map ball.hf ball.json -O only --only spreadsheet --resolution 24
if [ -s only/spreadsheet.png ] && [ ! -e only/frames ] && [ ! -e only/ball.mp4 ]; then pass "--only spreadsheet writes only it"; else fail "--only spreadsheet: $(ls -R only)"; fi

# --ghost adds the ghost the mapping lacks (the growing ball's: the largest ball) at its resolution.
run "--ghost 16 --only ghost" 0 "$frepkit" map ball.hf ball.json -O ghost --ghost 16 --only ghost
if [ -s ghost/ghost.png ] && [ ! -e ghost/frames ]; then pass "--only ghost writes only ghost.png"; else fail "--only ghost: $(ls -R ghost)"; fi
expect_in "the ghost at --ghost's resolution" "$(json ghost/manifest.json "[f['resolution'] for f in d['files'] if f['kind'] == 'ghost']")" "[16]"
run "--ghost 1" 1 "$frepkit" map ball.hf ball.json -O ghost1 --ghost 1
expect_in "--ghost 1 refused" "$err" "--ghost"

# --topology adds the map of the topology (the growing ball: one piece of genus 0 in every cell
# and frame, no change) at its resolution; with the spreadsheet, its overlay too.
run "--topology 12 --only spreadsheet,topology" 0 "$frepkit" map ball.hf ball.json -O topo --topology 12 --only spreadsheet,topology
if [ -s topo/spreadsheet-topology.png ] && [ -s topo/topology.png ] && [ ! -e topo/frames ]; then pass "--only topology writes the overlay and the chart"; else fail "--only topology: $(ls -R topo)"; fi
expect_in "the topology map in the manifest" "$(json topo/manifest.json "(d['topology']['resolution'], sorted(set(c['pieces'] for c in d['topology']['spreadsheet']['cells'])), sorted(set(d['topology']['frames']['pieces'])), len(d['topology']['frames']['changes']))")" "(12, [1], [1], 0)"
expect_in "the topology stage is reported" "$err" "topology"
run "--topology 1" 1 "$frepkit" map ball.hf ball.json -O topo1 --topology 1
expect_in "--topology 1 refused" "$err" "--topology"

# Bad mapping files: a clear error naming the place, exit code 1, nothing written.
bad() { # NAME JSON EXPECTED-TEXT
  printf '%s\n' "$2" >bad.json
  rm -rf badout
  run "bad mapping: $1" 1 "$frepkit" map ball.hf bad.json -O badout
  expect_in "bad mapping: $1: message" "$err" "$3"
  if [ ! -e badout ]; then pass "bad mapping: $1: nothing written"; else fail "bad mapping: $1: output written"; fi
}
world='"x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }], "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }], "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }]'
bad "unknown type" "{ \"coordinates\": { $world, \"x4\": [{ \"type\": \"dynamc\" }] } }" "coordinates.x4[0].type"
bad "missing coordinate" "{ \"coordinates\": { $world } }" "x4"
bad "overlapping world axes" '{ "coordinates": { "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "x" }], "x3": [{ "type": "world", "axis": "z" }], "x4": [{ "type": "dynamic", "range": [0, 1] }] } }' "coordinates.x2"
bad "zero frames" "{ \"coordinates\": { $world, \"x4\": [{ \"type\": \"dynamic\", \"range\": [0, 1] }] }, \"animation\": { \"duration\": 0 } }" "animation"
bad "zero-width range" "{ \"coordinates\": { $world, \"x4\": [{ \"type\": \"dynamic\", \"range\": [1, 1] }] } }" "coordinates.x4[0].range"
bad "one-point path" "{ \"coordinates\": { $world, \"x4\": [{ \"type\": \"dynamic\", \"range\": [0, 1] }] }, \"animation\": { \"path\": { \"coordinates\": [\"x4\"], \"points\": [[0.5]] } } }" "animation.path"
bad "syntax error" "{ \"coordinates\": { $world, }" "bad.json: 1:"
run "missing mapping file" 1 "$frepkit" map ball.hf nothere.json -O badout
expect_in "missing mapping file: message" "$err" "nothere.json"
printf '%s\n' 'my_model(x[4], a[1]) { my_model = x[4] - ; }' >broken.hf
run "model with a syntax error" 1 "$frepkit" map broken.hf ball.json -O badout
expect_in "model error names file:line:col" "$err" "broken.hf:1:"
if [ ! -e badout ]; then pass "model error: nothing written"; else fail "model error: output written"; fi

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
