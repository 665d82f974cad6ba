#!/usr/bin/env bash
# Every subcommand puts each of its outputs in place durably: fsync(temporary) -> rename ->
# fsync(directory), seen in strace (durable_write_check.py). One line per subcommand; map and
# demo are checked for a file of every kind they write.
#   frepkit_durable_writes_test.sh FREPKIT SOURCE_DIR
set -u
frepkit=$(realpath "$1")
source_dir=$(realpath "$2")
check="$source_dir/Testing/Apps/durable_write_check.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
work=$(realpath "$work")
cd "$work" || exit 1
robot="$source_dir/Examples/homotopic/robot.hf"
failures=0
durable() { # LABEL OUTPUTS(comma-separated, absolute) -- COMMAND...
  local label=$1
  shift
  echo "== $label"
  python3 "$check" "$@" || failures=$((failures + 1))
}

printf '0 0 0\n1 2 3\n-4 0.5 2\n' >points.txt
durable eval "$work/values.txt" -- "$frepkit" eval "$robot" -p points.txt --output "$work/values.txt"
durable mesh "$work/robot.stl" -- "$frepkit" mesh "$robot" --grid 24 -o "$work/robot.stl" -q
durable "slice png" "$work/robot.png" -- "$frepkit" slice "$robot" --fix x3=0 --grid 64 -o "$work/robot.png" -q
durable hfp "$work/shape.stl,$work/shape.wrl" -- \
  "$frepkit" hfp "$robot" -g 16 -stl "$work/shape.stl" -wrl "$work/shape.wrl"
cat >small.json <<'JSON'
{ "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2.4, 2.4] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2.4, 2.4] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2.4, 2.4] }],
    "x4": [{ "type": "dynamic", "range": [0, 1] },
           { "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.5 },
           { "type": "audio", "parameter": "pitch", "range": [0, 1], "target": [262, 523] }] },
  "animation": { "duration": 0.5, "fps": 6 },
  "world": { "resolution": 24 },
  "render": { "width": 64, "height": 48 } }
JSON
m="$work/map"
durable map "$m/spreadsheet.png,$m/frames/.fingerprint,$m/frames/frame_00000.png,$m/frames/frame_00002.png,$m/small.wav,$m/small.mp4,$m/manifest.json" -- \
  "$frepkit" map "$source_dir/Examples/mapping/morph4d.hf" small.json -O "$m" -q
d="$work/demo"
durable demo "$d/spreadsheet.png,$d/frames/frame_00000.png,$d/homotopic.wav,$d/homotopic.mp4,$d/cat.stl,$d/roblet.stl,$d/manifest.json" -- \
  "$frepkit" demo homotopic -O "$d" -q --frames 2 --resolution 8 --mesh-grid 16 \
  --examples "$source_dir/Examples"
echo "$failures subcommands failed"
[ "$failures" -eq 0 ]
