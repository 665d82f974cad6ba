#!/usr/bin/env bash
# Runs a command under its own virtual X server (the packaged VTK and ParaView render through X
# only). Unlike 'xvfb-run -a', the server picks a free display itself (-displayfd), so commands
# started at the same time never share or lose a display ("bad X server connection" seen with
# two xvfb-run -a at once). The command's exit code is returned.
#   Scripts/run-with-xvfb.sh COMMAND [ARGS...]
set -u
work=$(mktemp -d)
trap 'kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; rm -rf "$work"' EXIT
Xvfb -displayfd 3 -screen 0 1920x1200x24 -nolisten tcp -noreset 3>"$work/display" 2>"$work/log" &
server=$!
for _ in $(seq 200); do
  [ -s "$work/display" ] && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.05
done
if [ ! -s "$work/display" ]; then
  echo "run-with-xvfb.sh: Xvfb did not start:" >&2
  cat "$work/log" >&2
  exit 1
fi
export DISPLAY=":$(tr -d '[:space:]' <"$work/display")"
"$@"
