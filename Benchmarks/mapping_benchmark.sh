#!/usr/bin/env bash
# Time of the multimedia mapping of a 5-D model, stage by stage: the Homotopic Fun demo
# (Meta5D: a 5x5 spreadsheet and 240 frames at 1280x720, every cell and frame meshed at 128^3
# over the box, the sound track, the movie, the key shapes' STL) from scratch (--force), and the
# spreadsheet alone. frepkit's summary says where the workers' time went (meshing, drawing, PNG).
#   Benchmarks/mapping_benchmark.sh [FREPKIT] [OUTDIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
frepkit=${1:-"$here/../build/bin/frepkit"}
out=${2:-$(mktemp -d)}
echo "== frepkit demo homotopic (everything, from scratch) =="
/usr/bin/time -f "wall %e s, user %U s, sys %S s, max RSS %M KB" \
  "$frepkit" demo homotopic -O "$out/demo" --force
echo "== the 5x5 spreadsheet alone =="
/usr/bin/time -f "wall %e s, user %U s, sys %S s, max RSS %M KB" \
  "$frepkit" map "$here/../Examples/homotopic/meta5d.hf" "$here/../Examples/homotopic/homotopic.json" \
  -O "$out/spreadsheet" --only spreadsheet
