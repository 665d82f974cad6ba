#!/usr/bin/env bash
# Install.Prefix: `cmake --install BUILD --prefix PREFIX` into an empty folder outside the trees,
# then checks the installation as a user would get it:
#  - include/frepkit holds exactly the public headers (HEADERS file sets, VTK module classes);
#  - no installed file names the source or the build folder (grep -r), every RUNPATH is
#    $ORIGIN-relative;
#  - the installed frepkit runs with no LD_LIBRARY_PATH, loads its PNG module from <bin>/../lib
#    and finds the examples in <prefix>/share/frepkit/examples;
#  - the CMake package, the plug-in and FRepStudio's desktop entry are where they belong.
#   install_prefix_test.sh SOURCE_DIR BUILD_DIR PREFIX
set -euo pipefail
source_dir=$1 build_dir=$2 prefix=$3
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

rm -rf "$prefix"
mkdir -p "$prefix"
cmake --install "$build_dir" --prefix "$prefix" > "$prefix.install.log"
echo "installed $(find "$prefix" -type f | wc -l) files into $prefix"

# The tree a user gets.
for f in bin/frepkit bin/FRepStudio lib/libFRepKitEngine.so.0 lib/libFRepKitSources.so.0 \
  lib/cmake/frepkit/FRepKitConfig.cmake \
  lib/cmake/frepkit/FRepKitConfigVersion.cmake lib/cmake/frepkit/FRepKit-targets.cmake \
  lib/cmake/frepkit/FRepKit-vtk-module-properties.cmake \
  lib/paraview-5.11/plugins/FRepKit/FRepKit.so lib/paraview-5.11/plugins/frepkit.plugins.xml \
  include/frepkit/Compiler/model.h include/frepkit/vtkFRepSlice.h \
  share/frepkit/examples/homotopic/meta5d.hf share/frepkit/examples/consumer/CMakeLists.txt \
  share/doc/frepkit/README.md share/doc/frepkit/Documentation/architecture.md \
  share/applications/frepstudio.desktop share/icons/hicolor/scalable/apps/frepstudio.svg; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
grep -q '<Plugin name="FRepKit" auto_load="1"/>' \
  "$prefix/lib/paraview-5.11/plugins/frepkit.plugins.xml" || fail "frepkit.plugins.xml: no auto_load"
# What only Debian's ParaView in /usr needs is not installed under another prefix (Package.Deb
# checks it in /usr).
arch_dir=$(find "$prefix/lib" -mindepth 3 -maxdepth 3 -path '*/paraview-5.11/plugins' -not -path "$prefix/lib/paraview-5.11/*")
[ -z "$arch_dir" ] || fail "links for Debian's ParaView installed under a custom prefix: $arch_dir"
[ ! -e "$prefix/bin/paraview.conf" ] || fail "bin/paraview.conf installed under a custom prefix"

# Public headers only: every installed header is in a HEADERS file set or a module's list.
python3 - "$build_dir/public-headers.txt" "$prefix/include/frepkit" <<'PY' || failures=$((failures + 1))
import os, sys
listing, root = sys.argv[1], sys.argv[2]
expected = set()
for line in open(listing):
    line = line.strip()
    if not line:
        continue
    base, header = line.split("|", 1)
    if base == "module":
        expected.add(os.path.basename(header))
    else:
        expected.add(os.path.relpath(header, base))
found = set()
for folder, _, files in os.walk(root):
    for name in files:
        found.add(os.path.relpath(os.path.join(folder, name), root))
leaked = sorted(found - expected)
missing = sorted(expected - found)
print("include/frepkit: %d headers, %d public" % (len(found), len(expected)))
for name in leaked:
    print("FAILED: installed but not public: %s" % name)
for name in missing:
    print("FAILED: public but not installed: %s" % name)
sys.exit(1 if leaked or missing else 0)
PY

# Relocatable: no installed file names the source or build folder (links are not followed).
for tree in "$source_dir" "$build_dir"; do
  if hits=$(grep -rlF -- "$tree" "$prefix"); then
    fail "files name $tree:"; echo "$hits" | head -20
  fi
done
elf_count=0
while IFS= read -r -d '' f; do
  head -c 4 "$f" | grep -q $'\x7fELF' || continue
  elf_count=$((elf_count + 1))
  runpath=$(readelf -d "$f" | sed -n 's/.*(\(RUNPATH\|RPATH\)).*\[\(.*\)\]/\2/p')
  IFS=: read -r -a entries <<< "$runpath"
  for entry in "${entries[@]}"; do
    [[ $entry == '$ORIGIN'* ]] || fail "$f: RUNPATH entry '$entry' is not \$ORIGIN-relative"
  done
done < <(find "$prefix" -type f -print0)
echo "$elf_count ELF files, every RUNPATH \$ORIGIN-relative"

# The installed tool runs on its own.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
model="$prefix/share/frepkit/examples/homotopy5d.hf"
echo "0.5 0.5 0.5 0.5 0.25" | env -u LD_LIBRARY_PATH "$prefix/bin/frepkit" eval "$model" ||
  fail "installed frepkit eval"
env -u LD_LIBRARY_PATH "$prefix/bin/frepkit" slice "$model" --fix x3=0,x4=0.5,x5=0.5 \
  -o "$work/section.png" || fail "installed frepkit slice -> PNG"
[ -s "$work/section.png" ] || fail "no section.png"
# demo finds <prefix>/share/frepkit/examples by itself (a small run: 2 frames).
env -u LD_LIBRARY_PATH "$prefix/bin/frepkit" demo homotopic -O "$work/demo" --frames 2 \
  --resolution 24 > "$work/demo.log" 2>&1 || { cat "$work/demo.log"; fail "installed frepkit demo"; }
[ -s "$work/demo/spreadsheet.png" ] || fail "demo: no spreadsheet.png"

if [ "$failures" -ne 0 ]; then
  echo "Install.Prefix: $failures failures"
  exit 1
fi
echo "Install.Prefix: ok"
