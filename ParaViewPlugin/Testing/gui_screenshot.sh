#!/bin/sh
# A screenshot of ParaView's whole GUI with the FRepKit plug-in loaded, under Xvfb: the 4-D model
# morph4d.hf cut by FRep Slice's X4 slider (the Properties panel shows it). ParaView runs
# gui_screenshot_setup.py as its startup script; ffmpeg's x11grab grabs the X screen.
#   ParaViewPlugin/Testing/gui_screenshot.sh PLUGIN SOURCE_DIR OUTPUT.png
set -eu
plugin=$1
source_dir=$2
output=$3
display=:${FREPKIT_XVFB_DISPLAY:-97}
Xvfb "$display" -screen 0 1600x1000x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $paraview 2>/dev/null || true; kill $xvfb 2>/dev/null || true' EXIT
sleep 2
FREPKIT_PARAVIEW_PLUGIN=$plugin FREPKIT_SOURCE_DIR=$source_dir DISPLAY=$display \
  paraview --dr --script="$source_dir/ParaViewPlugin/Testing/Python/gui_screenshot_setup.py" \
  >/dev/null 2>&1 &
paraview=$!
sleep "${FREPKIT_GUI_WAIT:-25}"
# ParaView's main window opens at 1000 x 662 in the top-left corner (no window manager).
ffmpeg -loglevel error -y -f x11grab -video_size 1600x1000 -i "$display" -frames:v 1 \
  -vf crop=1000:662:0:0 "$output.tmp.png"
mv "$output.tmp.png" "$output"
