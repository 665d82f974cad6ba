#!/usr/bin/env bash
# frepkit's projection and space-time questions end to end: mesh --project of a moving sphere is
# its closed capsule-like sweep (and the sweep's volume is more than one frame's), slice and
# render take --project, query contact / presence / volume answer the analytic cases, and bad
# requests are exit code 1 with the reason, the output left alone.
# Without VTK (the sanitized build) the slice's .png picture is not available: the slice is
# checked as a mesh there.
#   frepkit_projection_test.sh FREPKIT MESH_CHECK vtk|novtk
set -u
frepkit=$(realpath "$1")
check=$(realpath "$2")
vtk=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
source "$(dirname "$0")/test_helpers.sh"

# A sphere of radius 0.5 moving from x = -1 to x = 1 as x4 goes 0 -> 1.
cat > "$work/moving.hf" <<'HF'
moving(x[4], a[1])
{
  moving = 0.25 - ((x[1] + 1 - 2*x[4])^2 + x[2]^2 + x[3]^2);
}
HF
box=(--box -1.6,-0.7,-0.7,1.6,0.7,0.7)
if run "mesh the sweep" 0 "$frepkit" mesh "$work/moving.hf" --project x4=0:1 "${box[@]}" \
  --grid 48 -o "$work/sweep.stl"; then
  expect_in "says what was projected" "$err" "projected along x4=0:1"
  [[ "$err" != *"fixed at 0"* ]] && pass "no note that the projected x4 is fixed" ||
    fail "a projected coordinate is said to be fixed: $err"
  run "the sweep is closed" 0 "$check" "$work/sweep.stl" --closed
  sweep_volume=$(echo "$out" | sed -n 's/.*volume \([0-9.e+-]*\).*/\1/p')
fi
run "mesh one frame" 0 "$frepkit" mesh "$work/moving.hf" --axes X,Y,Z,0 "${box[@]}" --grid 48 \
  -o "$work/frame.stl" && run "the frame is closed" 0 "$check" "$work/frame.stl" --closed
frame_volume=$(echo "$out" | sed -n 's/.*volume \([0-9.e+-]*\).*/\1/p')
# The capsule: a cylinder of length 2 and radius 0.5 with two half balls: 2.094 vs 0.524.
awk -v s="${sweep_volume:-0}" -v f="${frame_volume:-1}" \
  'BEGIN { exit !(s > 2.0 && s < 2.2 && f > 0.5 && f < 0.55) }' &&
  pass "sweep volume $sweep_volume (capsule 2.094), frame $frame_volume (ball 0.524)" ||
  fail "volumes: sweep '$sweep_volume' (capsule 2.094), frame '$frame_volume' (ball 0.524)"

if [ "$vtk" = vtk ]; then
  run "slice the sweep to a picture" 0 "$frepkit" slice "$work/moving.hf" --project x4=0:1 \
    --fix x3=0 --box -1.6,-0.7,1.6,0.7 --grid 64 -o "$work/sweep.png" -q
fi
run "slice the sweep to a mesh (x4 needs no --fix)" 0 "$frepkit" slice "$work/moving.hf" \
  --project x4=0:1 "${box[@]}" --grid 32 -o "$work/sweep-slice.stl" -q &&
  run "the sliced sweep is closed" 0 "$check" "$work/sweep-slice.stl" --closed
run "render the sweep" 0 "$frepkit" render "$work/moving.hf" --project x4=0:1 \
  --size 64x48 -o "$work/sweep-render.png" -q

# Two spheres approaching: radii 0.5 and 0.7 from x = -2 and 2 at speeds 1 and 2: t = 2.8/3.
cat > "$work/right.hf" <<'HF'
right(x[4], a[1]) { right = 0.49 - ((x[1] - 2 + 2*x[4])^2 + x[2]^2 + x[3]^2); }
HF
cat > "$work/left.hf" <<'HF'
left(x[4], a[1]) { left = 0.25 - ((x[1] + 2 - x[4])^2 + x[2]^2 + x[3]^2); }
HF
if run "query contact" 0 "$frepkit" query contact "$work/left.hf" "$work/right.hf" --time x4=0:2 \
  --box x1=-3:3,x2=-1:1,x3=-1:1; then
  t=$(echo "$out" | sed -n 's/first contact at x4 = \([0-9.e+-]*\).*/\1/p')
  awk -v t="${t:-0}" 'BEGIN { d = t - 2.8/3; exit !(d >= 0 && d < 2e-4) }' &&
    pass "contact at $t (analytic 0.93333)" || fail "contact: $out"
fi
run "query presence" 0 "$frepkit" query presence "$work/moving.hf" --time x4=0:1 --at 0,0,0
expect_in "inside while the sphere passes" "$out" "inside for x4 in [0.25"
run "query volume" 0 "$frepkit" query volume "$work/moving.hf" --time x4=0:1 --steps 3 \
  "${box[@]}" --grid 40 -o "$work/volume.csv"
expect_in "a table" "$(cat "$work/volume.csv")" "x4,volume,components"
[ "$(wc -l < "$work/volume.csv")" -eq 4 ] && pass "three times in the table" || fail "table: $(cat "$work/volume.csv")"

# A profile along a path: the ball of radius 0.5 along a polyline, swept: a capsule with a bend.
cat > "$work/ball.hf" <<'HF'
ball(x[3], a[1]) { ball = 0.25 - (x[1]^2 + x[2]^2 + x[3]^2); }
HF
if run "sweep a ball along a segment" 0 "$frepkit" sweep "$work/ball.hf" --path "-1,0,0;1,0,0" \
  -o "$work/along.hf"; then
  expect_in "says how to load it" "$err" "load it with --library $work/ball.hf"
  if run "mesh the swept ball" 0 "$frepkit" mesh "$work/along.hf" --library "$work/ball.hf" \
    --project x4=0:1 "${box[@]}" --grid 48 -o "$work/along.stl" -q; then
    run "its mesh is closed" 0 "$check" "$work/along.stl" --closed
    v=$(echo "$out" | sed -n 's/.*volume \([0-9.e+-]*\).*/\1/p')
    awk -v v="${v:-0}" 'BEGIN { exit !(v > 2.0 && v < 2.2) }' && pass "the capsule's volume: $v" ||
      fail "swept ball's volume '$v' (capsule 2.094)"
  fi
fi
run "sweep along a closed Catmull-Rom path, turned" 0 "$frepkit" sweep "$work/ball.hf" \
  --path "0,0,0;1,0,0;1,1,0" --closed --curve catmull-rom --orient tangent -o "$work/loop.hf"
run "the loop loads" 0 "$frepkit" check "$work/loop.hf" --library "$work/ball.hf"
run "a path of one point" 1 "$frepkit" sweep "$work/ball.hf" --path "0,0,0" -o "$work/kept.hf"
expect_in "says how many" "$err" "at least 2 points"
run "a bad path" 1 "$frepkit" sweep "$work/ball.hf" --path "0,0;1,1" -o "$work/kept.hf"
expect_in "says the syntax" "$err" "give X,Y,Z per point"
run "a 4-D profile" 1 "$frepkit" sweep "$work/moving.hf" --path "0,0,0;1,0,0" -o "$work/kept.hf"
expect_in "says 3-D" "$err" "a profile is 3-D"
[ ! -e "$work/kept.hf" ] && pass "refused sweeps wrote nothing" || fail "a refused sweep wrote a file"

# Two balls parting at x4 = 0.5: the topology's event.
cat > "$work/parting.hf" <<'HF'
parting(x[4], a[1]) { parting = max(0.25 - ((x[1]-x[4])^2 + x[2]^2 + x[3]^2), 0.25 - ((x[1]+x[4])^2 + x[2]^2 + x[3]^2)); }
HF
run "query topology" 0 "$frepkit" query topology "$work/parting.hf" --time x4=0.2:0.8 --steps 4 \
  --box x1=-2:2,x2=-1:1,x3=-1:1 --grid 65
expect_in "the event" "$out" "changes for x4 in [0.5, 0.50009765625]"
expect_in "what changed" "$out" "1 piece of genus 0 -> 2 pieces of genus 0"

echo "keep me" > "$work/kept.stl"
run "project along a coordinate the model lacks" 1 "$frepkit" mesh "$work/moving.hf" \
  --project x5=0:1 -o "$work/kept.stl"
expect_in "says which" "$err" "cannot project along x5: moving has x[4]"
run "an empty range" 1 "$frepkit" mesh "$work/moving.hf" --project x4=1:0 -o "$work/kept.stl"
expect_in "says lo <= hi" "$err" "lo <= hi"
run "a bad --project" 1 "$frepkit" mesh "$work/moving.hf" --project x4 -o "$work/kept.stl"
expect_in "says the syntax" "$err" "COORDINATE=LO:HI"
run "a tolerance <= 0" 1 "$frepkit" mesh "$work/moving.hf" --project x4=0:1 \
  --project-tolerance 0 -o "$work/kept.stl"
run "a band below the tolerance" 1 "$frepkit" mesh "$work/moving.hf" --project x4=0:1 \
  --project-band 1e-5 -o "$work/kept.stl"
expect_in "says why" "$err" "--project-band must be greater than --project-tolerance"
if run "mesh the sweep with every value exact" 0 "$frepkit" mesh "$work/moving.hf" --project x4=0:1 \
  --project-band inf "${box[@]}" --grid 32 -o "$work/exact.stl" -q; then
  run "it is closed too" 0 "$check" "$work/exact.stl" --closed
fi
[ "$(cat "$work/kept.stl")" == "keep me" ] && pass "failed runs left the output alone" ||
  fail "a failed run changed the output"
run "contact with one model" 1 "$frepkit" query contact "$work/left.hf" --time x4=0:1 --box -1,1,-1,1,-1,1
expect_in "says two" "$err" "takes 2 models"
run "contact without a box" 1 "$frepkit" query contact "$work/left.hf" "$work/right.hf" --time x4=0:1
expect_in "says --box" "$err" "needs --box"
run "presence without the point" 1 "$frepkit" query presence "$work/left.hf" --time x4=0:1 --at 0
expect_in "says how many" "$err" "give the 3 coordinates besides time"
run "time the model lacks" 1 "$frepkit" query presence "$work/left.hf" --time x7=0:1 --at 0,0,0
expect_in "says which" "$err" "time x7"
leftovers=$(find "$work" -name '*.tmp*' -o -name '.*frepkit*' | head -3)
[ -z "$leftovers" ] && pass "no temporary left" || fail "temporaries left: $leftovers"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
