#!/usr/bin/env bash
# frepkit --library end to end: the example user library (Examples/user-library/shapes.c) in
# eval (values against the formula), check, mesh (a closed mesh, culled by the interval form)
# and slice; a failing user function as a run-time error of its point; every broken library
# (Testing/Apps/user_libraries/bad_library.c) refused with exit code 1, naming the library and
# the function, never a crash.
#   frepkit_user_library_test.sh FREPKIT EXAMPLE_LIBRARY BAD_LIBRARY_DIR SOURCE_DIR MESH_CHECK
set -u
frepkit=$(realpath "$1")
library=$(realpath "$2")
bad=$(realpath "$3")
source_dir=$(realpath "$4")
check=$(realpath "$5")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0
source "$(dirname "$0")/test_helpers.sh"
cd "$work" || exit 1

cat > ring_only.hf <<'HF'
my_model(x[3], a[1]) { my_model = ring(x, 2.5, 0.8); }
HF
printf '2.5 0 0\n0 0 0\n3.3 0 0.1\n' > points.txt
if run "eval ring" 0 "$frepkit" eval --library "$library" ring_only.hf -p points.txt; then
  # ring(x, 2.5, 0.8) = 0.64 - (rho - 2.5)^2 - z^2
  expected=$(awk 'BEGIN { printf "%.6f %.6f %.6f", 0.64, 0.64 - 6.25, 0.64 - 0.64 - 0.01 }')
  got=$(echo "$out" | awk '{ printf "%.6f ", $NF }' | sed 's/ $//')
  expect_in "eval ring values" "$got" "$expected"
fi
run "check ring" 0 "$frepkit" check --library "$library" "$source_dir/Examples/user-library/ring.hf"
run "without the library the name is unknown" 1 "$frepkit" check ring_only.hf
expect_in "unknown name message" "$err" "Unassigned identificator"

if run "mesh ring" 0 "$frepkit" mesh --library "$library" "$source_dir/Examples/user-library/ring.hf" \
  -o ring.stl --box -4,-4,-2,4,4,2 --grid 64; then
  run "ring mesh is closed and oriented" 0 "$check" ring.stl --closed
fi
run "slice ring" 0 "$frepkit" slice --library "$library" ring_only.hf -o ring.vtp --box -4,-4,4,4 \
  --grid 64 --fix x3=0
run "map accepts --library" 0 "$frepkit" map --help
expect_in "map --library listed" "$out" "--library"

cat > arity.hf <<'HF'
my_model(x[3], a[1]) { my_model = ring(x, 2.5); }
HF
run "wrong arity" 1 "$frepkit" check --library "$library" arity.hf
expect_in "wrong arity names the signature" "$err" "ring takes 3 arguments, ring(array[3], real, real), but 2 given"

# waves(x, k) fails where k = 0: a run-time error of that point (NaN), not of the run.
cat > waves.hf <<'HF'
my_model(x[3], a[1]) { my_model = waves(x, x[3]); }
HF
printf '1 1 0\n1 1 1\n' > wpoints.txt
if run "eval failing user function" 0 "$frepkit" eval --library "$library" waves.hf -p wpoints.txt; then
  expect_in "failing point reported" "$out$err" "User function waves failed"
fi

run "missing library" 1 "$frepkit" check --library "$work/nothing.so" ring_only.hf
expect_in "missing library named" "$err" "user library $work/nothing.so: no such file"
echo "not a library" > junk.so
run "not a shared object" 1 "$frepkit" check --library junk.so ring_only.hf
expect_in "junk named" "$err" "user library junk.so: cannot be loaded"
run "no entry point" 1 "$frepkit" check --library "$bad/libfrepkit_bad_no_entry.so" ring_only.hf
expect_in "no entry named" "$err" "libfrepkit_bad_no_entry.so: has no entry point frepkit_user_register"
run "bad arity" 1 "$frepkit" check --library "$bad/libfrepkit_bad_bad_arity.so" ring_only.hf
expect_in "bad arity named" "$err" "libfrepkit_bad_bad_arity.so: function 'wide': bad arity 11"
run "duplicate" 1 "$frepkit" check --library "$bad/libfrepkit_bad_duplicate.so" ring_only.hf
expect_in "duplicate named" "$err" "libfrepkit_bad_duplicate.so: user function 'twin' is registered twice"
run "library name" 1 "$frepkit" check --library "$bad/libfrepkit_bad_library_name.so" ring_only.hf
expect_in "library clash named" "$err" "user function 'hfSphere': the name is a library function"
run "entry fails" 1 "$frepkit" check --library "$bad/libfrepkit_bad_entry_fails.so" ring_only.hf
expect_in "entry failure named" "$err" "frepkit_user_register failed with status 7"
run "same library twice" 1 "$frepkit" check --library "$library" --library "$library" ring_only.hf
expect_in "second load names the clash" "$err" "user function 'ring' is registered twice"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
