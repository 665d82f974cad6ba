#!/usr/bin/env bash
# Before/after figures for a change to the engine's region walks (the mesher, the ray caster,
# the tiled sampler, the normals' bricks, the solid bounds): each walker's benchmark on a fixed
# set of models, and the outputs they must keep byte for byte (meshes, slices, pictures, bounds)
# as SHA-256 sums. Run it before and after on a quiet machine and compare the two reports:
#   Benchmarks/engine_walks.sh BUILD_DIR OUT_DIR [PROSPERO_VM]
# PROSPERO_VM: the Prospero Challenge's tape (mkeeter/fidget models/prospero.vm; not shipped).
# Takes about 3 minutes on 2 cores. The report is OUT_DIR/report.md, the sums OUT_DIR/sums.txt.
set -euo pipefail
build=$(realpath "$1")
out=$(realpath -m "$2")
prospero=${3:-}
root=$(cd "$(dirname "$0")/.." && pwd)
bin="$build/bin"
mkdir -p "$out/files"
report="$out/report.md"
cd "$root"
{
  echo "# Engine walks, $(date -u '+%Y-%m-%d %H:%M UTC'), $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (uncommitted changes)')"
  echo "Machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg) at the start"
  echo
  echo "## Meshing (frep_mesh_benchmark --sizes 256 --repeat 3 --vtk-max-samples 0)"
  "$bin/frep_mesh_benchmark" --sizes 256 --models sphere,csg,HF_sample,union200_chain,max200_chain \
    --repeat 3 --vtk-max-samples 0
  echo
  echo "## Ray casting (frep_raycast_benchmark, 640x360, 2 threads)"
  for m in Examples/homotopic/cat.hf "Examples/homotopic/meta5d.hf --fix 0.5,0.5"; do
    # shellcheck disable=SC2086 # the model and its options
    "$bin/frep_raycast_benchmark" $m --size 640,360 --threads 2
  done
  echo
  echo "## Sampling (frep_sample_benchmark, median of 5, 2 threads)"
  "$bin/frep_sample_benchmark" Examples/homotopic/cat.hf --grid 128 --box -10,-10,-10,10,10,10 --repeat 5 --threads 2
  if [ -n "$prospero" ]; then
    "$bin/frep_sample_benchmark" "$prospero" --grid 1024 --repeat 7 --threads 2
  fi
  echo
  echo "## Solid bounds (frep_coordinate_bounds_benchmark)"
  "$bin/frep_coordinate_bounds_benchmark" Examples/homotopic/meta5d.hf
  "$bin/frep_coordinate_bounds_benchmark" Examples/homotopic/cat.hf
  echo
  echo "## Outputs (frepkit; wall seconds)"
  run() { # NAME COMMAND...
    local t0 t1
    t0=$(date +%s.%N)
    "$@" -q >/dev/null
    t1=$(date +%s.%N)
    printf '| %s | %.3f |\n' "${*:2:2} ${*:5:1}" "$(echo "$t1 - $t0" | bc)"
  }
  f="$out/files"
  run "$bin/frepkit" mesh Examples/homotopic/cat.hf -o "$f/cat.stl" --grid 160
  run "$bin/frepkit" slice Examples/homotopic/meta5d.hf -o "$f/meta5d.stl" --fix x4=0.3,x5=0.6 --grid 129 -j 1
  run "$bin/frepkit" mesh Examples/homotopic/robot.hf -o "$f/robot.ply" --grid 128
  run "$bin/frepkit" slice Examples/homotopic/nihon.hf -o "$f/nihon.png" --fix x3=0 --grid 512
  run "$bin/frepkit" render Examples/homotopic/meta5d.hf -o "$f/meta5d.png" --fix x4=0.5,x5=0.5 --size 480,360 --floor
  run "$bin/frepkit" render Examples/homotopic/roblet.hf -o "$f/roblet.png" --size 320,240
  if [ -n "$prospero" ]; then
    run "$bin/frepkit" slice "$prospero" -o "$f/prospero.png" --grid 1024 --box -1,-1,1,1
  fi
} 2>&1 | tee "$report"
(cd "$out/files" && sha256sum -- * >"$out/sums.txt")
echo "sums: $out/sums.txt"
