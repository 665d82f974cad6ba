#!/usr/bin/env bash
# End-to-end checks of ray casting from the command line: frepkit render (a ball's picture: its
# size, a lit centre, the background at the corners, against its baseline; bad views, sizes,
# formats and coordinate counts refused with the option named), and frepkit map with
# "render": {"method": "raycast"} (cells drawn without meshing, like the meshed ones) and
# {"scene": "floor"} (the paper's Fig. 8: the shape travelling over the checkerboard of the
# dynamic plane, ray-cast against a baseline frame, meshed like the ray-cast one), and bad
# render settings refused with the JSON place. Framing: without a box, what is not background
# in frepkit render's and slice's pictures, and the shape in a spreadsheet cell and a frame of
# frepkit map (a unit ball in [-10, 10]^3), spans at least half the picture's width or height.
#   frepkit_render_test.sh FREPKIT IMAGE_CHECK SOURCE_DIR
set -u
frepkit=$(realpath "$1")
image=$(realpath "$2")
source_dir=$(realpath "$3")
baselines="$source_dir/Testing/Data/Baseline"
work=$(mktemp -d)
trap '[ -n "${KEEP_WORK:-}" ] && echo "kept $work" || rm -rf "$work"' EXIT  # KEEP_WORK=1: keep the files
failures=0
checks=0
source "$(dirname "$0")/test_helpers.sh"
cd "$work" || exit 1
py=/usr/bin/python3

# pixel FILE X Y -> "r g b" (8-bit), from the PNG itself (zlib + the five filters).
cat >pixel.py <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
pos, idat, w, h, kind_of_colour, palette = 8, b'', 0, 0, 2, b''
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR':
        w, h = struct.unpack('>II', body[:8])
        kind_of_colour = body[9]
    elif kind == b'PLTE':
        palette = body
    elif kind == b'IDAT':
        idat += body
    pos += 12 + n
raw = zlib.decompress(idat)
bpp = 1 if kind_of_colour == 3 else 3  # frepkit writes 8-bit RGB, slice's pictures a palette
stride, rows, prev = bpp * w, [], bytearray(bpp * w)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b = prev[i]
        c = prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    prev = line
    rows.append(line if bpp == 3 else bytearray(b''.join(palette[3 * v:3 * v + 3] for v in line)))
if sys.argv[2] == 'bbox':  # the box of the pixels unlike the top-left one: "width height w h"
    bg, xs, ys = rows[0][0:3], [], []
    for y in range(h):
        for x in range(w):
            if max(abs(rows[y][3 * x + k] - bg[k]) for k in range(3)) > 8:
                xs.append(x)
                ys.append(y)
    print(w, h, max(xs) - min(xs) + 1 if xs else 0, max(ys) - min(ys) + 1 if ys else 0)
    sys.exit(0)
if sys.argv[2] == 'shape':  # the box of the coloured pixels (not white, grey or black text) in
    x0, y0, rw, rh = (int(v) for v in sys.argv[3:7])  # the rectangle: "width height w h"
    xs, ys = [], []
    for y in range(y0, y0 + rh):
        for x in range(x0, x0 + rw):
            p = rows[y][3 * x:3 * x + 3]
            if max(p) - min(p) > 40:
                xs.append(x)
                ys.append(y)
    print(rw, rh, max(xs) - min(xs) + 1 if xs else 0, max(ys) - min(ys) + 1 if ys else 0)
    sys.exit(0)
x, y = int(sys.argv[2]), int(sys.argv[3])
print(*rows[y][3 * x:3 * x + 3])
PY
pixel() { "$py" pixel.py "$@"; }
png_size() { "$py" -c "import struct,sys; b=open(sys.argv[1],'rb').read(24); print(*struct.unpack('>II', b[16:24]))" "$1"; }
field() { echo "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }
below() { [[ "$1" =~ ^[0-9.eE+-]+$ ]] && awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

# --- frepkit render ----------------------------------------------------------------------------
printf '%s\n' 'my_model(x[3], a[1]) { my_model = 1 - x[1] * x[1] - x[2] * x[2] - x[3] * x[3]; }' >ball.hf
run "render a ball (the box framed)" 0 "$frepkit" render ball.hf -o ball.png --box -2,-2,-2,2,2,2 --size 160,120 --frame box
expect_in "render reports the rays" "$err" "rays ("
if [ "$(png_size ball.png)" = "160 120" ]; then pass "picture is 160x120"; else fail "picture size $(png_size ball.png)"; fi
read -r r g b < <(pixel ball.png 80 60)
if [ "$r" -gt 120 ] && [ "$r" -lt 255 ] && [ "$r" -gt "$b" ]; then pass "centre lit in the shape colour ($r $g $b)"; else fail "centre pixel $r $g $b"; fi
if [ "$(pixel ball.png 2 2)" = "255 255 255" ]; then pass "corner is the background"; else fail "corner $(pixel ball.png 2 2)"; fi
line=$("$image" compare ball.png "$baselines/raycast_ball.png")
if below "$(field differing_fraction "$line")" 0.01; then pass "ball against its baseline ($line)"; else fail "ball against its baseline: $line"; fi
run "1 and 2 threads: same picture" 0 "$frepkit" render ball.hf -o ball1.png --box -2,-2,-2,2,2,2 --size 160,120 -j1 --floor
run "floor" 0 "$frepkit" render ball.hf -o ball2.png --box -2,-2,-2,2,2,2 --size 160,120 -j2 --floor
if cmp -s ball1.png ball2.png; then pass "floor pictures identical for 1 and 2 threads"; else fail "pictures differ between 1 and 2 threads"; fi

# Framing: without --box the solid's own bounds are the box, so the picture frames the solid
# (the -10..10 default left a unit ball a few pixels wide): what is not background spans at least
# half the picture's width or height, with the floor too.
frames() { # NAME PNG [X Y W H: the shape's coloured pixels in that rectangle]
  if [ $# -gt 2 ]; then read -r w h bw bh < <(pixel "$2" shape "$3" "$4" "$5" "$6"); else read -r w h bw bh < <(pixel "$2" bbox); fi
  if [ $((2 * bw)) -ge "$w" ] || [ $((2 * bh)) -ge "$h" ]; then pass "$1 ($bw x $bh of $w x $h)"; else fail "$1: $bw x $bh of $w x $h"; fi
}
run "render a ball without --box" 0 "$frepkit" render ball.hf -o framed.png --size 160,120
expect_in "render names the solid's box" "$err" "(the solid's bounds; --box to choose)"
frames "render frames the ball" framed.png
# The camera fits the ball's silhouette (raycast::frame_shape), not its box's corners: nearly the
# picture's height (fill 0.9), with a box of the solid's bounds and with a larger box alike.
for box in "" "--box -2,-2,-2,2,2,2"; do
  # shellcheck disable=SC2086 # the box option's two words, or none
  run "render a ball ${box:-without --box}: the solid framed" 0 "$frepkit" render ball.hf -o tight.png --size 160,120 $box
  read -r w h bw bh < <(pixel tight.png bbox)
  if [ $((4 * bh)) -ge $((3 * h)) ] && [ "$bh" -lt "$h" ]; then pass "the ball spans ${bh} of ${h} rows (${box:-no box})"; else fail "the ball spans $bw x $bh of $w x $h (${box:-no box})"; fi
done
run "bad --frame refused" 1 "$frepkit" render ball.hf -o x.png --frame corners
expect_in "bad --frame named" "$err" "--frame"
run "render a ball on the floor without --box" 0 "$frepkit" render ball.hf -o framed_floor.png --size 160,120 --floor
frames "render frames the ball and its floor" framed_floor.png
printf '%s\n' 'my_model(x[2], a[1]) { my_model = 0.04 - x[1] * x[1] - x[2] * x[2]; }' >small_disc.hf
run "slice a small disc without --box" 0 "$frepkit" slice small_disc.hf -o small_disc.png
frames "slice frames the disc" small_disc.png

# The mapping's cells and frames frame the solids, not the model box: a unit ball in [-10, 10]^3
# (x4 changes nothing) covers at least half of a spreadsheet cell and of a frame, meshed or
# ray-cast (the frame's caption is grey: only the shape's colour counts there).
printf '%s\n' 'my_model(x[4], a[1]) { my_model = 1 - x[1] * x[1] - x[2] * x[2] - x[3] * x[3]; }' >ball4.hf
cat >framing.json <<'JSON'
{
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-10, 10] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-10, 10] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-10, 10] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 1 },
           { "type": "dynamic", "range": [0, 1] }]
  },
  "world": { "resolution": 48 },
  "animation": { "duration": 1, "fps": 2 },
  "spreadsheet": { "cell_size": 96, "labels": false },
  "render": { "width": 160, "height": 120, "inset": false }
}
JSON
for method in mesh raycast; do
  run "map a unit ball in [-10, 10]^3 ($method)" 0 "$frepkit" map ball4.hf framing.json -O "framed_$method" --only spreadsheet,frames --method "$method" -q
  rect=$("$py" -c "import json,sys; m=json.load(open(sys.argv[1])); print(*[f for f in m['files'] if f['kind'] == 'spreadsheet'][0]['cells'][0]['rect'])" "framed_$method/manifest.json")
  # shellcheck disable=SC2086 # the rectangle's four numbers
  frames "a spreadsheet cell frames the ball ($method)" "framed_$method/spreadsheet.png" $rect
  frames "a frame frames the ball ($method)" "framed_$method/frames/frame_00001.png" 0 0 160 120
done

run "bad --view refused" 1 "$frepkit" render ball.hf -o x.png --view 10,nan
expect_in "bad --view named" "$err" "--view"
run "bad --size refused" 1 "$frepkit" render ball.hf -o x.png --size 0,10
expect_in "bad --size named" "$err" "--size"
run "non-png refused" 1 "$frepkit" render ball.hf -o x.stl
expect_in "format named" "$err" ".png"
printf '%s\n' 'my_model(x[2], a[1]) { my_model = 1 - x[1] * x[1] - x[2] * x[2]; }' >disc.hf
run "2 free coordinates refused" 1 "$frepkit" render disc.hf -o x.png
expect_in "3-D needed" "$err" "3 free coordinates"
run "bad colour refused" 1 "$frepkit" render ball.hf -o x.png --colour 2,0,0
expect_in "bad colour named" "$err" "--colour"
if ls x.png* >/dev/null 2>&1; then fail "a refused render left a file"; else pass "refused renders write nothing"; fi

# --- frepkit map, ray-cast ------------------------------------------------------------------
# A 5-D ball: its radius grows with x4 and x5, both dynamic and on the spreadsheet's grid.
printf '%s\n' 'my_model(x[5], a[1]) { r = 0.6 + 0.5 * x[4] + 0.3 * x[5]; my_model = r * r - x[1] * x[1] - x[2] * x[2] - x[3] * x[3]; }' >ball5.hf
mapping() { # METHOD SCENE SYSTEM
  cat <<JSON
{
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.5 },
           { "type": "dynamic", "range": [0, 1] }],
    "x5": [{ "type": "spreadsheet", "axis": "rows", "range": [0, 1], "step": 0.5 },
           { "type": "dynamic", "range": [0, 1] }]
  },
  "world": { "system": "$3", "resolution": 32 },
  "animation": { "duration": 1, "fps": 3,
                 "path": { "coordinates": ["x4", "x5"], "points": [[0, 0], [1, 0], [1, 1]] } },
  "spreadsheet": { "cell_size": 96, "spacing": 0.1, "labels": false },
  "render": { "width": 320, "height": 180, "method": "$1", "scene": "$2" }
}
JSON
}
mapping raycast page cartesian >raycast.json
mapping mesh page cartesian >mesh.json
mapping raycast floor cartesian >floor.json
run "map, ray-cast cells" 0 "$frepkit" map ball5.hf raycast.json -O rc --only spreadsheet
expect_in "ray-cast: no meshing" "$err" "meshing 0.0 s"
run "map, meshed cells" 0 "$frepkit" map ball5.hf mesh.json -O ms --only spreadsheet
line=$("$image" compare rc/spreadsheet.png ms/spreadsheet.png)
if below "$(field differing_fraction "$line")" 0.03; then pass "ray-cast and meshed spreadsheets agree ($line)"; else fail "ray-cast vs meshed spreadsheet: $line"; fi
run "map, the floor scene" 0 "$frepkit" map ball5.hf floor.json -O fl --only frames
for k in 0 1 2; do
  if [ -s "fl/frames/frame_0000$k.png" ]; then pass "floor frame $k written"; else fail "floor frame $k missing"; fi
done
if cmp -s fl/frames/frame_00000.png fl/frames/frame_00002.png; then fail "the shape does not move over the floor"; else pass "frames differ as the shape travels"; fi
line=$("$image" compare fl/frames/frame_00001.png "$baselines/raycast_floor_frame.png")
if below "$(field differing_fraction "$line")" 0.01; then pass "floor frame against its baseline ($line)"; else fail "floor frame against its baseline: $line"; fi

sed 's/"method": "raycast"/"method": "rays"/' raycast.json >bad_method.json
run "unknown method refused" 1 "$frepkit" map ball5.hf bad_method.json -O bad1
expect_in "method place named" "$err" "render.method"
mapping raycast page cylindrical >cyl.json
"$py" - cyl.json <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
for name, axis in (("x1", "r"), ("x2", "phi"), ("x3", "z")):
    j["coordinates"][name][0]["axis"] = axis
j["coordinates"]["x1"][0]["range"] = [0.1, 2]
json.dump(j, open(sys.argv[1], "w"))
PY
run "ray casting a bent world refused" 1 "$frepkit" map ball5.hf cyl.json -O bad2
expect_in "bent world: render.method named" "$err" "render.method"
mapping mesh floor cartesian >floor_mesh.json
run "map, the floor scene meshed" 0 "$frepkit" map ball5.hf floor_mesh.json -O flm --only frames
line=$("$image" compare flm/frames/frame_00001.png fl/frames/frame_00001.png)
if below "$(field differing_fraction "$line")" 0.03; then pass "meshed and ray-cast floor frames agree ($line)"; else fail "meshed vs ray-cast floor frame: $line"; fi
"$py" - floor_mesh.json <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
del j["coordinates"]["x5"][1]  # x5 no longer dynamic: one dynamic coordinate
j["coordinates"]["x5"].append({"type": "fixed", "value": 0.5})
j["animation"].pop("path")
json.dump(j, open("floor_1d.json", "w"))
PY
run "floor scene needs two dynamic coordinates" 1 "$frepkit" map ball5.hf floor_1d.json -O bad3
expect_in "floor scene: render.scene named" "$err" "render.scene"
for d in bad1 bad2 bad3; do
  if [ -e "$d" ] && [ -n "$(ls -A "$d")" ]; then fail "$d: a refused mapping wrote files"; else pass "$d: nothing written"; fi
done

echo "$checks checks, $failures failures"
[ "$failures" -eq 0 ]
