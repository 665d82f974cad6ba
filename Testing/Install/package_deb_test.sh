#!/usr/bin/env bash
# Package.Deb: makes the Debian package (cpack -G DEB), installs it into this machine with
# apt-get, checks what a user of the package gets, and removes it again:
#  - frepkit from PATH runs the main job (frepkit demo homotopic, the full demo);
#  - /usr/bin/python3 imports the Python package frepkit;
#  - pvpython loads the plug-in by name from ParaView's own plug-in folder, and auto-loads it
#    from its plugins XML there (auto_load="1");
#  - FRepStudio starts under Xvfb and writes a screenshot.
# Needs root (it installs into /usr): CI runs as root on a throw-away machine. Idempotent: a
# frepkit package left installed is removed first, and the package is removed on every exit.
#   package_deb_test.sh SOURCE_DIR BUILD_DIR VERSION
set -uo pipefail
source_dir=$1 build_dir=$2 version=$3
if [ "$(id -u)" -ne 0 ]; then
  echo "FAILED: Package.Deb installs the package into /usr with apt-get and needs root" \
    "(CI runs as root); run it as root or exclude it: ctest -E Package.Deb"
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }
work=$(mktemp -d /tmp/frepkit-deb.XXXXXX)
remove_package() {
  if dpkg-query -W -f="\${db:Status-Abbrev}" frepkit 2>/dev/null | grep -q "^[ir]"; then
    apt-get remove --purge -y frepkit > "$work/remove.log" 2>&1 || cat "$work/remove.log"
  fi
}
trap 'remove_package; rm -rf "$work"' EXIT
remove_package

start=$SECONDS
(cd "$build_dir" && cpack -G DEB -B "$work/package") > "$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; echo "FAILED: cpack -G DEB"; exit 1; }
deb="$work/package/frepkit_${version}_amd64.deb"
[ -f "$deb" ] || { ls "$work/package"; echo "FAILED: no $(basename "$deb")"; exit 1; }
echo "made $(basename "$deb") ($(du -h "$deb" | cut -f1)) in $((SECONDS - start)) s"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for package in paraview python3-paraview ffmpeg fonts-dejavu-core libsndfile1 libqt5widgets5; do
  [[ ", $depends," == *", $package"[\ ,]* ]] || fail "Depends lacks $package"
done

start=$SECONDS
(cd "$work/package" && apt-get install -y "./$(basename "$deb")") > "$work/install.log" 2>&1 ||
  { cat "$work/install.log"; echo "FAILED: apt-get install"; exit 1; }
echo "apt-get install: $((SECONDS - start)) s"
hash -r

# frepkit from PATH: the main job.
[ "$(command -v frepkit)" = /usr/bin/frepkit ] || fail "frepkit is not /usr/bin/frepkit on PATH"
start=$SECONDS
(cd "$work" && env -u LD_LIBRARY_PATH frepkit demo homotopic -O "$work/homotopic") \
  > "$work/demo.log" 2>&1 || { tail -20 "$work/demo.log"; fail "frepkit demo homotopic"; }
for f in spreadsheet.png path.png manifest.json cat.stl; do
  [ -s "$work/homotopic/$f" ] || fail "frepkit demo: no $f"
done
compgen -G "$work/homotopic/*.mp4" > /dev/null || fail "frepkit demo: no movie (.mp4)"
echo "frepkit demo homotopic: $((SECONDS - start)) s, $(ls "$work/homotopic" | wc -l) outputs"

# Python: the package frepkit in /usr/lib/python3/dist-packages.
if (cd "$work" && /usr/bin/python3 -c "import frepkit; print('import frepkit:', frepkit.__file__)"); then
  :
else
  fail "/usr/bin/python3 -c 'import frepkit'"
fi

# The plug-in from ParaView's own folder: by name, and auto-loaded from its plugins XML.
model=/usr/share/frepkit/examples/homotopy5d.hf
plugin_dir=/usr/lib/x86_64-linux-gnu/paraview-5.11/plugins
[ -e "$plugin_dir/FRepKit/FRepKit.so" ] || fail "no $plugin_dir/FRepKit/FRepKit.so"
(cd "$work" && pvpython "$source_dir/Testing/Install/installed_plugin.py" name "$model") ||
  fail "pvpython: LoadDistributedPlugin('FRepKit') from $plugin_dir"
(cd "$work" && PV_PLUGIN_CONFIG_FILE="$plugin_dir/frepkit.plugins.xml" \
  pvpython "$source_dir/Testing/Install/installed_plugin.py" config "$model") ||
  fail "pvpython: auto-load from $plugin_dir/frepkit.plugins.xml"

# The GUI auto-loads it (paraview.conf -> frepkit.plugins.xml).
(cd "$work" && FREPKIT_RESULT="$work/gui.txt" "$source_dir/Scripts/run-with-xvfb.sh" \
  paraview --script="$source_dir/Testing/Install/gui_autoload.py" --exit) > "$work/gui.log" 2>&1
if grep -q "FRepKit loaded" "$work/gui.txt" 2>/dev/null; then
  echo "paraview GUI: $(cat "$work/gui.txt")"
else
  tail -20 "$work/gui.log"; fail "the paraview GUI did not auto-load FRepKit"
fi

# FRepStudio starts (under its own X server) and renders a model.
(cd "$work" && "$source_dir/Scripts/run-with-xvfb.sh" FRepStudio --screenshot "$work/studio.png" \
  --size 800x500 /usr/share/frepkit/examples/homotopic/meta5d.hf --set x4=0.5 --set x5=0.5) \
  > "$work/studio.log" 2>&1 || { cat "$work/studio.log"; fail "FRepStudio --screenshot"; }
[ -s "$work/studio.png" ] && echo "FRepStudio: screenshot $(stat -c %s "$work/studio.png") bytes" ||
  fail "FRepStudio wrote no screenshot"
[ -f /usr/share/applications/frepstudio.desktop ] || fail "no frepstudio.desktop"

remove_package
[ ! -e /usr/bin/frepkit ] && [ ! -e "$plugin_dir/FRepKit" ] || fail "apt-get remove left files"
if [ "$failures" -ne 0 ]; then
  echo "Package.Deb: $failures failures"
  exit 1
fi
echo "Package.Deb: ok"
