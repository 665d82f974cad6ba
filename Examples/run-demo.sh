#!/usr/bin/env bash
# The main job: "Homotopic Fun in 5D Space" end to end. One 5-D HyperFun function, Meta5D,
# blends four key shapes of different topology — Cat, Robot, NiHon, Rob_let, the files in
# Examples/homotopic/ — and Examples/homotopic/homotopic.json maps it onto multimedia coordinates:
# writes into OUTDIR (default ./out/homotopic)
#   meta5d.hf        Meta5D as drawn: the paper's blend, keys aligned by size, written by the
#                    metamorphosis component (frepkit demo --align none: the paper's formula)
#   spreadsheet.png  the 5x5 spreadsheet of 3-D cross-sections (x4 across, x5 down)
#   path.png         the closed path through the (x4, x5) plane with every frame's point
#   homotopic.mp4    10 s at 24 fps, 1280x720, with the checkerboard inset and the sound track
#   homotopic.wav    the sound track (pitch follows x4, loudness x5)
#   frames/          the 240 frames as PNG (kept: a second run resumes instead of redrawing)
#   cat.stl robot.stl nihon.stl roblet.stl   the key shapes as binary STL
#   manifest.json    everything written, with each cell's and frame's coordinate values
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
frepkit=${FREPKIT:-"$here/../build/bin/frepkit"}
out=${1:-out/homotopic}
"$frepkit" demo homotopic -O "$out" --examples "$here"
