#!/usr/bin/env bash
# Gathers a harness's seed corpus into OUT (emptied first): the shared HyperFun material and the
# examples are copied at test time, never committed here; the small hand-made seeds and the
# regression inputs (crashes found, now fixed) are committed under corpus/ and regressions/.
# Usage: collect_seeds.sh HARNESS SOURCE_DIR SHARED_DIR OUT
set -euo pipefail
harness=$1
source_dir=$2
shared_dir=$3
out=$4
rm -rf "$out" && mkdir -p "$out"

# copy_tree DIR PATTERN: every file matching PATTERN under DIR, named after its path (two
# conformance folders hold files of the same name).
copy_tree() {
  local dir=$1 pattern=$2 file name
  [ -d "$dir" ] || { echo "collect_seeds: no folder $dir" >&2; exit 1; }
  while IFS= read -r -d '' file; do
    name=${file#"$dir"/}
    cp "$file" "$out/$(basename "$dir")__${name//\//__}"
  done < <(find "$dir" -type f -name "$pattern" -print0)
}

fuzz_dir="$source_dir/Testing/Fuzz"
case "$harness" in
  fuzz_hyperfun_parser|fuzz_hyperfun_eval)
    copy_tree "$shared_dir/hyperfun/conformance" '*.hf'
    copy_tree "$shared_dir/hyperfun/models" '*.hf'
    copy_tree "$source_dir/Examples" '*.hf'
    ;;
  fuzz_mapping_plan)
    copy_tree "$source_dir/Examples" '*.json'
    ;;
  fuzz_vm_reader)
    copy_tree "$source_dir/Examples" '*.vm'
    ;;
  fuzz_points_reader|fuzz_hfp_arguments)
    ;;
  *)
    echo "collect_seeds: unknown harness $harness" >&2
    exit 1
    ;;
esac
for extra in "$fuzz_dir/corpus/$harness" "$fuzz_dir/regressions/$harness"; do
  if [ -d "$extra" ]; then
    copy_tree "$extra" '*'
  fi
done
count=$(find "$out" -type f | wc -l)
if [ "$count" -eq 0 ]; then
  echo "collect_seeds: no seed for $harness" >&2
  exit 1
fi
echo "collect_seeds: $count seeds for $harness"
