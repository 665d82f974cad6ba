#!/usr/bin/env bash
# Install.Consumer: builds the example consumer project, as installed in
# PREFIX/share/frepkit/examples/consumer, against the installation only (find_package(FRepKit)
# with CMAKE_PREFIX_PATH=PREFIX, in a folder outside the trees), runs it and checks its output:
# triangles > 0 and the engine's F at a point equal to `frepkit eval`'s.
#   install_consumer_test.sh SOURCE_DIR BUILD_DIR PREFIX [COMPILER_LAUNCHER]
set -euo pipefail
source_dir=$1 build_dir=$2 prefix=$3 launcher=${4:-}
work=$(mktemp -d /tmp/frepkit-consumer.XXXXXX)
trap 'rm -rf "$work"' EXIT
configure=(-DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release)
if [ -n "$launcher" ]; then
  configure+=("-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher")
fi
cmake -S "$prefix/share/frepkit/examples/consumer" -B "$work/build" "${configure[@]}" \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
grep "FRepKit_DIR" "$work/build/CMakeCache.txt"
cmake --build "$work/build" -j2 > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
# Nothing of the source or build tree was used (include paths, library paths, config files).
if grep -rlF -e "$source_dir" -e "$build_dir" "$work/build"; then
  echo "FAILED: the consumer's build refers to the FRepKit source or build tree"
  exit 1
fi

model="$prefix/share/frepkit/examples/homotopy5d.hf"
point="0.5 0.5 0.5 0.5 0.25"
# shellcheck disable=SC2086
out=$(env -u LD_LIBRARY_PATH "$work/build/frepkit_consumer" "$model" "$work/slice.vtp" $point)
echo "$out"
expected=$(echo "$point" | env -u LD_LIBRARY_PATH "$prefix/bin/frepkit" eval "$model")
echo "frepkit eval: $expected"
value=$(echo "$out" | sed -n 's/^F = //p')
triangles=$(echo "$out" | sed -n 's/^triangles = \([0-9]*\).*/\1/p')
[ -n "$value" ] && [ "$value" = "$expected" ] ||
  { echo "FAILED: consumer F = '$value', frepkit eval = '$expected'"; exit 1; }
[ -n "$triangles" ] && [ "$triangles" -gt 0 ] || { echo "FAILED: no triangles"; exit 1; }
[ -s "$work/slice.vtp" ] || { echo "FAILED: no slice.vtp"; exit 1; }
echo "Install.Consumer: ok"
