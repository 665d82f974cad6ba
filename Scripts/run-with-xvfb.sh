#!/usr/bin/env bash
# Runs a command under its own virtual X server (the packaged VTK and ParaView render through X
# only). Unlike 'xvfb-run -a', the server picks a free display itself (-displayfd), so commands
# started at the same time never share or lose a display ("bad X server connection" seen with
# two xvfb-run -a at once). The command's exit code is returned.
#   Scripts/run-with-xvfb.sh COMMAND [ARGS...]
set -u
work=$(mktemp -d)
trap 'kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; rm -rf "$work"' EXIT
# Two servers started at the same instant can still race for one display's lock and one of them
# exits at once (seen once in a ctest -j2 run: a test failed in 0.5 s): start again, up to 5 times.
server=""
for attempt in 1 2 3 4 5; do
  : >"$work/display"
  Xvfb -displayfd 3 -screen 0 1920x1200x24 -nolisten tcp -noreset 3>"$work/display" 2>"$work/log" &
  server=$!
  for _ in $(seq 200); do
    [ -s "$work/display" ] && break
    kill -0 "$server" 2>/dev/null || break
    sleep 0.05
  done
  [ -s "$work/display" ] && break
  kill "$server" 2>/dev/null
  wait "$server" 2>/dev/null
  sleep "0.$((RANDOM % 9 + 1))"
done
if [ ! -s "$work/display" ]; then
  echo "run-with-xvfb.sh: Xvfb did not start (5 attempts):" >&2
  cat "$work/log" >&2
  exit 1
fi
export DISPLAY=":$(tr -d '[:space:]' <"$work/display")"
"$@"
