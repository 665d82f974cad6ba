#!/usr/bin/env bash
# frepkit morph end to end: the four key shapes of Homotopic Fun on a 2 x 2 lattice are the
# paper's Meta5D value for value (eval against Examples/homotopic/meta5d.hf), in the library form
# (--library the keys) and the pasted one (one file, no library); a mid cell meshes closed; the
# spline schemes write loadable models; aligned keys keep exact corners; a bad lattice, a missing key or a clash of names is exit
# code 1 with the reason, leaving the output file as it was and no temporary behind.
# Without VTK, --normalise distance is refused before anything is written (its distances are .vti).
#   frepkit_morph_test.sh FREPKIT SOURCE_DIR MESH_CHECK vtk|novtk
set -u
frepkit=$(realpath "$1")
source_dir=$(realpath "$2")
check=$(realpath "$3")
vtk=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
source "$(dirname "$0")/test_helpers.sh"
cd "$source_dir/Examples/homotopic" || exit 1
keys=(cat.hf robot.hf nihon.hf roblet.hf)
libraries=(--library cat.hf --library robot.hf --library nihon.hf --library roblet.hf)

# Points over the box and the lattice, its corners and edges included.
awk 'BEGIN { srand(7); for (i = 0; i < 300; i++) {
  t4 = (i < 9) ? (i % 3) / 2 : rand(); t5 = (i < 9) ? int(i / 3) / 2 : rand();
  printf "%.6f %.6f %.6f %.17g %.17g\n", 20*rand()-10, 20*rand()-10, 20*rand()-10, t4, t5 } }' \
  > "$work/points.txt"
run "paper's Meta5D" 0 "$frepkit" eval meta5d.hf --object meta5d -p "$work/points.txt"
paper=$out

if run "morph 2x2 (library form)" 0 "$frepkit" morph "${keys[@]}" --lattice 2x2 -o "$work/lib.hf"; then
  expect_in "says how to load it" "$err" "load it with --library cat.hf --library robot.hf"
  run "eval the library form" 0 "$frepkit" eval "$work/lib.hf" "${libraries[@]}" -p "$work/points.txt"
  [ "$out" == "$paper" ] && pass "library form = meta5d at 300 points" ||
    fail "library form differs from meta5d.hf: $(diff <(echo "$out") <(echo "$paper") | head -4)"
  run "without the keys it does not load" 1 "$frepkit" check "$work/lib.hf"
fi
if run "morph 2x2 --paste" 0 "$frepkit" morph "${keys[@]}" --lattice 2x2 --paste --name meta -o "$work/one.hf"; then
  run "eval the pasted form alone" 0 "$frepkit" eval "$work/one.hf" -p "$work/points.txt"
  [ "$out" == "$paper" ] && pass "pasted form = meta5d at 300 points" ||
    fail "pasted form differs from meta5d.hf: $(diff <(echo "$out") <(echo "$paper") | head -4)"
  if run "mesh the middle cell" 0 "$frepkit" mesh "$work/one.hf" --axes X,Y,Z,0.5,0.5 --grid 48 \
    -o "$work/mid.stl"; then
    run "the middle cell is closed" 0 "$check" "$work/mid.stl" --closed
  fi
fi
# Aligned keys (centroids and sizes): the corners are still the keys exactly.
awk 'BEGIN { srand(11); for (i = 0; i < 40; i++)
  printf "%.6f %.6f %.6f %d %d\n", 20*rand()-10, 20*rand()-10, 20*rand()-10, i % 2, int(i / 2) % 2 }' \
  > "$work/corners.txt"
run "paper's corners" 0 "$frepkit" eval meta5d.hf --object meta5d -p "$work/corners.txt"
corners=$out
if run "morph --align size" 0 "$frepkit" morph "${keys[@]}" --lattice 2x2 --align size --paste \
  -o "$work/aligned.hf"; then
  run "eval the aligned morph" 0 "$frepkit" eval "$work/aligned.hf" -p "$work/corners.txt"
  [ "$out" == "$corners" ] && pass "aligned corners = the keys at 40 points" ||
    fail "aligned corners differ: $(diff <(echo "$out") <(echo "$corners") | head -4)"
  expect_in "the frame is written" "$(cat "$work/aligned.hf")" "the moving frame"
fi
# Timed and weighted: the corners are still the keys; the middle moves toward the heavier key.
if run "morph --timing ease --key-weight" 0 "$frepkit" morph "${keys[@]}" --lattice 2x2 --paste \
  --timing ease --key-weight nihon=3 --key-weight "robot=1 + max(mx[3], 0)" -o "$work/weighted.hf"; then
  run "eval the weighted morph" 0 "$frepkit" eval "$work/weighted.hf" -p "$work/corners.txt"
  [ "$out" == "$corners" ] && pass "weighted corners = the keys at 40 points" ||
    fail "weighted corners differ: $(diff <(echo "$out") <(echo "$corners") | head -4)"
  expect_in "the weights are written" "$(cat "$work/weighted.hf")" "mg2 = max((3), 0.001);"
fi
run "key weight without =" 1 "$frepkit" morph cat.hf robot.hf --key-weight cat -o "$work/kept.hf"
expect_in "key weight form explained" "$err" "give KEY=EXPRESSION"
run "bad key weight" 1 "$frepkit" morph cat.hf robot.hf --key-weight "cat=2 +* 1" -o "$work/kept.hf"
expect_in "bad key weight at its column" "$err" "key weight 'cat':1:4: error"
run "key weight with catmull-rom" 1 "$frepkit" morph cat.hf robot.hf --key-weight cat=2 \
  --scheme catmull-rom -o "$work/kept.hf"
expect_in "catmull-rom refused" "$err" "never negative"
run "bad timing" 1 "$frepkit" morph cat.hf robot.hf --timing hold:1 -o "$work/kept.hf"
expect_in "timing explained" "$err" "not a timing"

for scheme in catmull-rom b-spline; do
  if run "morph 5 keys, $scheme" 0 "$frepkit" morph cat.hf robot.hf nihon.hf roblet.hf cat.hf:cat \
    --scheme "$scheme" --paste -o "$work/$scheme.hf"; then
    printf '0 0 0 0\n0 0 0 1\n1 2 0 0.3\n' > "$work/p4.txt"
    run "eval $scheme" 0 "$frepkit" eval "$work/$scheme.hf" -p "$work/p4.txt"
    first=$(echo "$out" | sed -n 1p)
    last=$(echo "$out" | sed -n 2p)
    [ "$first" == "$last" ] && pass "$scheme: both ends are the Cat" ||
      fail "$scheme: ends $first and $last differ"
  fi
done

# Normalised by distance: the distances written beside the model as .vti; loaded again with the
# --shape arguments frepkit prints, the corners keep the keys' signs (the zero sets) exactly.
if [ "$vtk" = novtk ]; then
  run "--normalise distance without VTK" 1 "$frepkit" morph cat.hf nihon.hf --normalise distance \
    --paste -o "$work/nd.hf"
  expect_in "needs VTK" "$err" "--normalise distance needs a frepkit built with VTK"
  if [ ! -e "$work/nd.hf" ] && [ ! -e "$work/nd-cat-distance.vti" ]; then
    pass "nothing written without VTK"
  else
    fail "a refused --normalise left files behind"
  fi
elif run "morph --normalise distance" 0 "$frepkit" morph cat.hf nihon.hf --normalise distance --paste \
  -o "$work/nd.hf"; then
  for k in cat nihon; do
    [ -s "$work/nd-$k-distance.vti" ] && pass "nd-$k-distance.vti written" || fail "nd-$k-distance.vti missing"
  done
  expect_in "the shapes to load it with" "$err" "--shape mdist_cat=$work/nd-cat-distance.vti --shape mdist_nihon=$work/nd-nihon-distance.vti"
  awk 'BEGIN { srand(5); for (i = 0; i < 400; i++) print -9 + 18 * rand(), -9 + 18 * rand(), -9 + 18 * rand() }' > "$work/p3.txt"
  for corner in "cat 0" "nihon 1"; do
    set -- $corner
    awk -v t="$2" '{ print $0, t }' "$work/p3.txt" > "$work/p4.txt"
    blend=$("$frepkit" eval "$work/nd.hf" -p "$work/p4.txt" --shape "mdist_cat=$work/nd-cat-distance.vti" \
      --shape "mdist_nihon=$work/nd-nihon-distance.vti" | awk '{ print ($1 >= 0) }')
    own=$("$frepkit" eval "$1.hf" -o "$1" -p "$work/p3.txt" | awk '{ print ($1 >= 0) }')
    if [ "$(echo "$blend" | wc -l)" -eq 400 ] && [ "$blend" == "$own" ]; then
      pass "normalised, x4 = $2 is inside exactly where $1 is (400 points)"
    else
      fail "normalised, x4 = $2: the sides differ from $1's"
    fi
  done
fi
run "distances need a file" 1 "$frepkit" morph cat.hf nihon.hf --normalise distance -o -
expect_in "distances to stdout refused" "$err" "give -o FILE"

echo "keep me" > "$work/kept.hf"
run "lattice that does not match" 1 "$frepkit" morph "${keys[@]}" --lattice 3x2 -o "$work/kept.hf"
expect_in "lattice message" "$err" "the lattice 3 x 2 has 6 nodes, 4 keys were given"
run "missing key" 1 "$frepkit" morph cat.hf "$work/none.hf" -o "$work/kept.hf"
expect_in "missing key named" "$err" "none.hf"
run "unknown object" 1 "$frepkit" morph cat.hf robot.hf:dog -o "$work/kept.hf"
expect_in "unknown object named" "$err" "dog"
run "clashing names" 1 "$frepkit" morph cat.hf cat.hf --name cat -o "$work/kept.hf"
expect_in "clash explained" "$err" "an object the metamorphosis writes"
run "bad lattice text" 1 "$frepkit" morph cat.hf robot.hf --lattice 2by1 -o "$work/kept.hf"
expect_in "lattice syntax explained" "$err" "node counts joined by x"
[ "$(cat "$work/kept.hf")" == "keep me" ] && pass "failed runs left the output alone" ||
  fail "a failed run changed the output"
leftovers=$(find "$work" -name '*.tmp*' -o -name '.*frepkit*' | head -3)
[ -z "$leftovers" ] && pass "no temporary left" || fail "temporaries left: $leftovers"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
