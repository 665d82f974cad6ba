#!/usr/bin/env bash
# A VTK-free build of FRepKit has the whole command line, `frepkit map` and `frepkit demo`
# included (issue 13): configure the source tree with FREPKIT_ENABLE_VTK=OFF in a build of its
# own, build frepkit, check that nothing of VTK is linked, and run a mapping file end to end.
# Usage: vtk_free_build_test.sh SOURCE_DIR BUILD_DIR [COMPILER_LAUNCHER]
set -u
source_dir=$1
build_dir=$2
launcher=${3:-}
work="$build_dir/work"
checks=0
failures=0
source "$source_dir/Testing/Apps/test_helpers.sh"
rm -rf "$work" && mkdir -p "$work"

configure=(cmake -S "$source_dir" -B "$build_dir/tree" -DCMAKE_BUILD_TYPE=Release
  -DFREPKIT_ENABLE_VTK=OFF -DFREPKIT_BUILD_TESTING=OFF -DFREPKIT_BUILD_BENCHMARKS=OFF)
if [ -n "$launcher" ]; then
  configure+=("-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher" "-DCMAKE_C_COMPILER_LAUNCHER=$launcher")
fi
run "configure with FREPKIT_ENABLE_VTK=OFF" 0 "${configure[@]}" || { echo "$err"; exit 1; }
expect_in "no ParaView or VTK is looked for" "$out" "Build files have been written"
if [[ "$out" == *"ParaView"* ]]; then fail "the VTK-free configuration mentions ParaView"; fi

run "build frepkit" 0 cmake --build "$build_dir/tree" -j2 --target frepkit || { echo "$err" | tail -30; exit 1; }
frepkit="$build_dir/tree/bin/frepkit"

# The names of the linked libraries (not their paths: this build's own folder says "vtk-free").
linked=$(ldd "$frepkit" | awk '{print $1}')
if echo "$linked" | grep -qE '^libvtk|paraview|^libQt5'; then
  fail "frepkit links VTK, ParaView or Qt: $(echo "$linked" | grep -E '^libvtk|paraview|^libQt5' | head -3)"
else
  pass "frepkit links neither VTK nor Qt"
fi

run "frepkit --help lists map and demo" 0 "$frepkit" --help
expect_in "map is a subcommand" "$out" "map"
expect_in "demo is a subcommand" "$out" "demo"

run "frepkit map: the spreadsheet of the 4-D morph" 0 "$frepkit" map \
  "$source_dir/Examples/mapping/morph4d.hf" "$source_dir/Examples/mapping/spreadsheet-1d.json" \
  -O "$work/map"
for f in spreadsheet.png manifest.json; do
  if [ -s "$work/map/$f" ]; then pass "map wrote $f"; else fail "map did not write $f"; fi
done
if head -c 8 "$work/map/spreadsheet.png" | od -An -c | grep -q "P   N   G"; then
  pass "spreadsheet.png is a PNG"
else
  fail "spreadsheet.png is not a PNG"
fi
leftovers=$(find "$work/map" -name '*.tmp-*' | head -3)
if [ -z "$leftovers" ]; then pass "no temporary left"; else fail "temporaries left: $leftovers"; fi

run "frepkit map: a bad mapping file is refused with its place" 1 "$frepkit" map \
  "$source_dir/Examples/mapping/morph4d.hf" /dev/null -O "$work/bad"

echo "$checks checks, $failures failures"
[ "$failures" -eq 0 ]
