#!/usr/bin/env bash
# The main job until the Homotopic Fun demo exists: check a 5-D HyperFun model and draw its
# z = 0 cross-sections at the four corners and the centre of the (x4, x5) square, evaluated by
# the compiled engine through `frepkit eval`. '#' marks F >= 0 (inside).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
frepkit=${FREPKIT:-"$here/../build/bin/frepkit"}
model="$here/homotopy5d.hf"

"$frepkit" check "$model"

for corner in "0 0" "1 0" "0 1" "1 1" "0.5 0.5"; do
  set -- $corner
  echo
  echo "x4 = $1, x5 = $2 (z = 0):"
  awk -v u="$1" -v w="$2" 'BEGIN {
    for (j = 0; j < 21; j++) for (i = 0; i < 41; i++)
      printf "%.6f %.6f 0 %s %s\n", -5 + i * 0.25, 5 - j * 0.5, u, w }' |
    "$frepkit" eval "$model" |
    awk '{ c = ($1 == "nan" || $1 ~ /^error/) ? "?" : ($1 >= 0 ? "#" : ".");
           line = line c; if (NR % 41 == 0) { print "  " line; line = "" } }'
done
