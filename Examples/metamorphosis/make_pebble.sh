#!/usr/bin/env bash
# Regenerates pebble.stl from pebble.hf (binary STL, about 4,700 triangles, closed, genus 0).
#   Examples/metamorphosis/make_pebble.sh build/bin/frepkit
set -eu
frepkit=${1:-frepkit}
here=$(cd "$(dirname "$0")" && pwd)
"$frepkit" mesh "$here/pebble.hf" -o "$here/pebble.stl" --box -2.2,-1.6,-1.6,2,1.6,1.8 --grid 28 \
  --no-normals -q
