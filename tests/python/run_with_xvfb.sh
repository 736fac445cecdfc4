#!/usr/bin/env bash
# Runs a command under an X server of its own. Xvfb picks a free display
# itself (-displayfd) and names it once it accepts connections, so tests run
# in parallel never race for a display number, as xvfb-run -a's guess from
# lock files can (a stale lock, or two servers picking the same number).
# -noreset: by default an X server resets when its last client disconnects,
# and drops a client that connects meanwhile ("bad X server connection");
# a test that opens one window after another closes hits that window.
#
#   run_with_xvfb.sh COMMAND [ARG...]
set -uo pipefail
tmp=$(mktemp -d)
mkfifo "$tmp/display"
Xvfb -displayfd 3 -screen 0 320x240x24 -nolisten tcp -noreset 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; rm -rf "$tmp"' EXIT
if ! read -r -t 30 number <"$tmp/display"; then
  echo "run_with_xvfb.sh: error: Xvfb did not start: $(tail -n 1 "$tmp/xvfb.log")" >&2
  exit 1
fi
DISPLAY=:$number "$@"
