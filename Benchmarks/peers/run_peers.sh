#!/usr/bin/env bash
# The peer benchmark in one run: builds the original HyperFun interpreter + hfp and libfive from
# the source directories you name (nothing is downloaded), then runs them and FRepKit on the
# same points, grids and tapes and prints markdown tables (also written to a results file).
#
#   Benchmarks/peers/run_peers.sh --libfive-src DIR --hyperfun-src DIR --prospero FILE
#       [--frepkit-build DIR]   FRepKit's build tree (default: <repo>/build; must be built)
#       [--build-dir DIR]       where the peers are built and the points go (default /work/peers-build)
#       [--shared DIR]          the shared models folder (default: <repo>/../shared)
#       [--out FILE]            results file (default: <build-dir>/peers-results.md)
#       [--quick]               time limit 20 s per cell (slow cells are reported
#                               "skipped (> limit)")
#       [--limit SECONDS]       time limit per meshing cell (default 900)
#       [--eval-limit SECONDS]  time limit per evaluation cell (default 120)
#       [--jobs N]              build parallelism (default 1)
#       [--only LIST]           any of eval,mesh,prospero (default all three)
# See README.md for what each column measures.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
libfive_src="" hyperfun_src="" prospero="" frepkit_build="$repo/build" build_dir="/work/peers-build"
shared="$repo/../shared" out="" limit=900 eval_limit=120 jobs=1 only="eval,mesh,prospero"
points=1000000 original_points=20000 samples=256 threads=2 pixels=1024
command_line="$0 $*"

die() { echo "run_peers.sh: $*" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --libfive-src) libfive_src="$2"; shift 2 ;;
    --hyperfun-src) hyperfun_src="$2"; shift 2 ;;
    --prospero) prospero="$2"; shift 2 ;;
    --frepkit-build) frepkit_build="$2"; shift 2 ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --shared) shared="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --quick) limit=20; eval_limit=20; shift ;;
    --limit) limit="$2"; shift 2 ;;
    --eval-limit) eval_limit="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) die "unknown option $1 (see --help)" ;;
  esac
done

# --- the named directories -----------------------------------------------------------------------
[ -n "$libfive_src" ] || die "--libfive-src DIR is required (a libfive checkout, e.g. git --git-dir=MIRROR archive HEAD | tar -x -C DIR)"
[ -f "$libfive_src/libfive/include/libfive/tree/tree.hpp" ] || die "--libfive-src $libfive_src: not a libfive source tree (no libfive/include/libfive/tree/tree.hpp)"
[ -n "$hyperfun_src" ] || die "--hyperfun-src DIR is required (a checkout of pmur002/hyperfun, the R package)"
[ -f "$hyperfun_src/src/cppinterpreter_lib/hfinterpreter.h" ] || die "--hyperfun-src $hyperfun_src: not the pmur002/hyperfun sources (no src/cppinterpreter_lib/hfinterpreter.h)"
[ -n "$prospero" ] || die "--prospero FILE is required (prospero.vm from mkeeter/fidget models/)"
[ -f "$prospero" ] || die "--prospero $prospero: no such file"
head -c 4096 "$prospero" | grep -q "var-x" || die "--prospero $prospero: not a .vm tape (no var-x)"
[ -f "$frepkit_build/lib/libFRepKitEngine.so" ] || die "--frepkit-build $frepkit_build: no lib/libFRepKitEngine.so (build FRepKit first)"
[ -d "$shared/hyperfun/models" ] || die "--shared $shared: no hyperfun/models folder"
libfive_src="$(cd "$libfive_src" && pwd)" hyperfun_src="$(cd "$hyperfun_src" && pwd)"
prospero="$(cd "$(dirname "$prospero")" && pwd)/$(basename "$prospero")"
shared="$(cd "$shared" && pwd)"
mkdir -p "$build_dir"
build_dir="$(cd "$build_dir" && pwd)"
[ -n "$out" ] || out="$build_dir/peers-results.md"

# --- build ---------------------------------------------------------------------------------------
echo "run_peers.sh: building the peers in $build_dir (log: $build_dir/build.log)" >&2
{
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
    -DLIBFIVE_SOURCE_DIR="$libfive_src" -DHYPERFUN_SOURCE_DIR="$hyperfun_src" \
    -DFREPKIT_BUILD_DIR="$frepkit_build" &&
  cmake --build "$build_dir" -j "$jobs" --target hfp hyperfun_driver frepkit_driver libfive_driver
} > "$build_dir/build.log" 2>&1 || { tail -30 "$build_dir/build.log" >&2; die "build failed (see $build_dir/build.log)"; }

run="$build_dir/run"
mkdir -p "$run"
fk="$build_dir/frepkit_driver" hf="$build_dir/hyperfun_driver" lf="$build_dir/libfive_driver"

# --- helpers -------------------------------------------------------------------------------------
# cell LIMIT NAME CMD...: runs a driver under the time limit (seconds); sets $res to its RESULT
# line, or to "STATUS=..." when it did not finish; its stderr goes to $run/NAME.log.
cell() {
  local limit="$1" name="$2"; shift 2
  local status=0
  # (the outer subshell keeps bash's "Killed" notice of a timed-out driver off the terminal)
  ( (ulimit -v 16000000; exec timeout --signal=KILL "$limit" "$@") < /dev/null > "$run/$name.out" 2> "$run/$name.log" ) 2> /dev/null || status=$?
  res="$(grep '^RESULT' "$run/$name.out" | tail -1 || true)"
  if [ "$status" -eq 137 ]; then
    res="STATUS=skipped (> ${limit} s limit)"
  elif [ "$status" -gt 128 ]; then
    res="STATUS=crashed (signal $((status - 128)); $(tail -c 200 "$run/$name.log" | tr '\n' ' ' | sed 's/ *$//'))"
  elif [ "$status" -ne 0 ] || [ -z "$res" ]; then
    res="STATUS=failed (exit $status: $(tail -1 "$run/$name.log"))"
  fi
  echo "  $name: $res" >&2
}
get() { # get KEY: the value of KEY in $res (empty if absent)
  sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<< " ${res#RESULT}"
}
status_or() { # status_or VALUE: VALUE, or the cell's status when it did not finish
  if [[ "$res" == STATUS=* ]]; then echo "${res#STATUS=}"
  elif [ -n "$(get cannot_translate)" ]; then echo "cannot translate ($(sed -n 's/.*cannot_translate="\([^"]*\)".*/\1/p' <<< "$res"))"
  else echo "$1"; fi
}
ratio() { # ratio A B: A/B to 2 significant digits, or — when either is not a number
  awk -v a="$1" -v b="$2" 'BEGIN { if (a ~ /^[0-9.e+-]+$/ && b ~ /^[0-9.e+-]+$/ && b + 0 > 0) printf (a / b >= 10 ? "%.0fx" : "%.2gx"), a / b; else printf "—" }'
}
commit_of() { git -C "$1" rev-parse HEAD 2>/dev/null || echo "not a git checkout"; }

# --- header --------------------------------------------------------------------------------------
report="$run/report.md"
{
  echo "# FRepKit and its peers, side by side ($(date -u '+%Y-%m-%d %H:%M UTC'))"
  echo
  echo "- Machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(free -g | awk '/Mem:/ {print $2}') GiB; $(. /etc/os-release && echo "$PRETTY_NAME"); $(c++ --version | head -1)"
  echo "- Load when starting: $(cut -d' ' -f1-3 /proc/loadavg) (1/5/15 min)"
  echo "- FRepKit: $(commit_of "$repo")$(git -C "$repo" diff --quiet HEAD 2>/dev/null || echo ' (with uncommitted changes)'), engine $frepkit_build/lib/libFRepKitEngine.so"
  echo "- libfive: $libfive_src $( [ -f "$libfive_src/.peer-commit" ] && cat "$libfive_src/.peer-commit" || commit_of "$libfive_src")"
  echo "- HyperFun (pmur002/hyperfun): $hyperfun_src $( [ -f "$hyperfun_src/.peer-commit" ] && cat "$hyperfun_src/.peer-commit" || commit_of "$hyperfun_src")"
  echo "- Prospero: $prospero ($(wc -l < "$prospero") lines, sha256 $(sha256sum "$prospero" | cut -c1-16))"
  echo "- Command: \`$command_line\`"
  echo "- Time limit per cell: evaluation $eval_limit s, meshing and Prospero $limit s; threads: $threads (the original: 1)"
  echo
} > "$report"

"$fk" workloads "$shared" "$run/models" > "$run/workloads.tsv"
rm -f "$run/libfive_unbuilt"

# hfp itself (the command-line program) on W1 at its default grid, to show it builds and runs.
w1_model="$(awk -F'\t' '$1 == "W1" {print $3}' "$run/workloads.tsv")"
hfp_check="$("$build_dir/hfp" "$w1_model" -usedc 0 -b 10 2>&1 | sed -n 's/^triangles: //p')"
echo "- hfp command line, \`hfp W1 -usedc 0 -b 10\` (30 cells): ${hfp_check:-failed} triangles" >> "$report"
echo >> "$report"

# --- evaluation ----------------------------------------------------------------------------------
if [[ ",$only," == *,eval,* ]]; then
  echo "run_peers.sh: evaluation" >&2
  {
    echo "## Evaluation: million points per second"
    echo
    echo "The same $points points per workload, uniform in its box (seed 42; the original: the first $original_points of them, 1 thread, one point per call); libfive: its array evaluator, f32, 256-point batches, $threads threads; FRepKit: BatchEvaluator, f64, $threads threads. Medians of at least 3 passes and 0.5 s."
    echo
    echo "| workload | original | libfive f32 | FRepKit f64 | FRepKit / original | FRepKit / libfive | FRepKit vs original: identical values | libfive f32 vs FRepKit: max \|diff\| / max(1,\|F\|) |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|"
  } >> "$report"
  while IFS=$'\t' read -r id label model object box; do
    pts="$run/points_$id.bin"
    [ -f "$pts" ] || "$fk" points "$box" "$points" 42 "$pts"
    cell "$eval_limit" "eval_${id}_frepkit" "$fk" eval "$model" "$object" "$pts" "$run/values_${id}_frepkit.bin" "$threads"
    fk_mpps="$(status_or "$(get mpps)")"
    cell "$eval_limit" "eval_${id}_original" "$hf" eval "$model" "$object" "$pts" "$original_points" "$run/values_${id}_original.bin"
    or_mpps="$(status_or "$(get mpps)")"
    same="—"
    if [[ "$res" != STATUS=* ]]; then
      cell "$eval_limit" "compare_${id}_original" "$fk" compare "$run/values_${id}_original.bin" "$run/values_${id}_frepkit.bin" "$original_points"
      same="$(get identical) of $(get points)"
      [ "$(get max_abs)" = "0" ] || same="$same (max \|diff\| $(get max_abs))"
    fi
    cell "$eval_limit" "eval_${id}_libfive" "$lf" eval "$model" "$object" "$pts" "$run/values_${id}_libfive.bin" "$threads"
    lf_mpps="$(status_or "$(get mpps)")"
    # A tree libfive could not even prepare for evaluation is not meshed (it would only time out).
    [[ "$res" == STATUS=skipped* ]] && echo "$id" >> "$run/libfive_unbuilt"
    lf_diff="—"
    if [[ "$res" != STATUS=* ]] && [ -z "$(get cannot_translate)" ]; then
      cell "$eval_limit" "compare_${id}_libfive" "$fk" compare "$run/values_${id}_frepkit.bin" "$run/values_${id}_libfive.bin"
      lf_diff="$(get max_rel)"
      [ "$(get sign_differs)" = "0" ] || lf_diff="$lf_diff ($(get sign_differs) signs differ)"
    fi
    echo "| $label | $or_mpps | $lf_mpps | $fk_mpps | $(ratio "$fk_mpps" "$or_mpps") | $(ratio "$fk_mpps" "$lf_mpps") | $same | $lf_diff |" >> "$report"
  done < "$run/workloads.tsv"
  echo >> "$report"
fi

# --- meshing -------------------------------------------------------------------------------------
if [[ ",$only," == *,mesh,* ]]; then
  echo "run_peers.sh: meshing" >&2
  {
    echo "## Meshing at ${samples}^3 samples: seconds (triangles)"
    echo
    echo "From reading the model to the finished mesh, nothing written. hfp: its marching-cubes engine (\`-usedc 0\`, hfp's defaults) through its own classes with $((samples - 1)) cells = $samples samples per axis (hfp's -g stops at 250); libfive: Mesh::render (dual contouring), min_feature for 256 octree cells per axis, $threads workers; FRepKit: extract_surface, $threads threads."
    echo
    echo "| workload | hfp -usedc 0 | libfive | FRepKit | hfp / FRepKit | libfive / FRepKit |"
    echo "|---|---:|---:|---:|---:|---:|"
  } >> "$report"
  touch "$run/libfive_unbuilt"
  while IFS=$'\t' read -r id label model object box; do
    cell "$limit" "mesh_${id}_frepkit" "$fk" mesh "$model" "$object" "$box" "$samples" "$threads"
    fk_s="$(status_or "$(get seconds)")"; fk_t="$(get triangles)"
    cell "$limit" "mesh_${id}_hfp" "$hf" mesh "$model" "$object" "$box" "$samples"
    hf_s="$(status_or "$(get seconds)")"; hf_t="$(get triangles)"
    if grep -qx "$id" "$run/libfive_unbuilt"; then
      lf_s="not run: its tree did not build in the evaluation (> $eval_limit s)"; lf_t=""
    else
      cell "$limit" "mesh_${id}_libfive" "$lf" mesh "$model" "$object" "$box" "$samples" "$threads"
      lf_s="$(status_or "$(get seconds)")"; lf_t="$(get triangles)"
    fi
    fmt() { if [ -n "$2" ]; then printf '%.3g (%s)' "$1" "$2"; else printf '%s' "$1"; fi; }
    echo "| $label | $(fmt "$hf_s" "$hf_t") | $(fmt "$lf_s" "$lf_t") | $(fmt "$fk_s" "$fk_t") | $(ratio "$hf_s" "$fk_s") | $(ratio "$lf_s" "$fk_s") |" >> "$report"
  done < "$run/workloads.tsv"
  echo >> "$report"
fi

# --- Prospero ------------------------------------------------------------------------------------
if [[ ",$only," == *,prospero,* ]]; then
  echo "run_peers.sh: Prospero" >&2
  {
    echo "## Prospero: ${pixels}x${pixels} sign image over [-1,1]^2, seconds"
    echo
    echo "| program | seconds | inside pixels | notes |"
    echo "|---|---:|---:|---|"
  } >> "$report"
  cell "$limit" prospero_libfive "$lf" slice "$prospero" "$pixels" "$threads"
  if [[ "$res" == STATUS=* ]]; then
    echo "| libfive | $(status_or x) | | |" >> "$report"
  else
    echo "| libfive Heightmap::render (interval pruning, tape pushing), $threads workers | $(printf %.3g "$(get render_seconds)") | $(get render_inside) | pixel centres; tree translated from FRepKit's tape of the .vm |" >> "$report"
    echo "| libfive ArrayEvaluator brute force, 256-point batches, $threads threads | $(printf %.3g "$(get brute_seconds)") | $(get brute_inside) | the same pixels |" >> "$report"
  fi
  cell "$limit" prospero_frepkit "$fk" slice "$prospero" "$pixels" "$threads"
  echo "| FRepKit sample_grid (per-tile tape simplification), $threads threads | $(status_or "$(printf %.3g "$(get seconds)" 2>/dev/null)") | $(get inside) | the same pixel centres |" >> "$report"
  if [ -x "$frepkit_build/bin/frepkit" ]; then
    start=$(date +%s.%N)
    line="$("$frepkit_build/bin/frepkit" slice "$prospero" --grid "$pixels" --box -1,-1,1,1 --threads "$threads" -o "$run/prospero.png" 2>&1 | tail -1)" || line="failed: $line"
    wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.3g", e - s }')
    reported="$(sed -n 's/.*, \([0-9.e+-]*\) s (axes.*/\1/p' <<< "$line")"
    inside="$(sed -n 's/.*, \([0-9]*\) of [0-9]* samples inside.*/\1/p' <<< "$line")"
    echo "| \`frepkit slice prospero.vm --grid $pixels --box -1,-1,1,1 --threads $threads -o p.png\`: the time it reports | ${reported:-?} | ${inside:-?} | whole command (wall, with start-up and PNG): $wall s |" >> "$report"
  else
    echo "| frepkit slice | not run | | no $frepkit_build/bin/frepkit |" >> "$report"
  fi
  echo >> "$report"
fi

cp "$report" "$out"
cat "$report"
echo "run_peers.sh: written to $out (driver logs in $run)" >&2
