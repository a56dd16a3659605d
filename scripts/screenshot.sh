#!/usr/bin/env bash
# Takes the README's screenshot of the editor: starts Xvfb on a free display,
# opens build/bin/whitted on scenes/seed.json, waits for the render to finish,
# and writes the whole screen to docs/images/editor.png. Safe to re-run.
# Needs xvfb, x11-utils (xwininfo) and imagemagick (import). Build first
# (scripts/setup.sh). Usage: scripts/screenshot.sh [OUT.png]
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=${1:-docs/images/editor.png}
size=1600x1000x24

fail() {
  echo "screenshot: $*" >&2
  exit 1
}

[[ -x build/bin/whitted ]] || fail "build/bin/whitted is not built (run scripts/setup.sh)"
for tool in Xvfb xwininfo import; do
  command -v "$tool" >/dev/null 2>&1 || fail "$tool not found (apt-get install xvfb x11-utils imagemagick)"
done

# A display nobody uses: no lock file and no socket.
display=
for n in $(seq 97 140); do
  if [[ ! -e /tmp/.X$n-lock && ! -e /tmp/.X11-unix/X$n ]]; then
    display=:$n
    break
  fi
done
[[ -n "$display" ]] || fail "no free X display between :97 and :140"

xvfb_pid=
editor_pid=
home=$(mktemp -d)
cleanup() {
  local status=$?
  set +e
  for pid in $editor_pid $xvfb_pid; do
    kill "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
  done
  rm -rf "$home"
  exit "$status"
}
trap cleanup EXIT

Xvfb "$display" -screen 0 "$size" -nolisten tcp >"$home/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 50); do
  DISPLAY=$display xwininfo -root >/dev/null 2>&1 && break
  kill -0 "$xvfb_pid" 2>/dev/null || fail "Xvfb did not start on $display: $(cat "$home/xvfb.log")"
  sleep 0.1
done
DISPLAY=$display xwininfo -root >/dev/null 2>&1 || fail "Xvfb on $display does not answer"

# A fresh settings directory, so a saved window layout or recent-files list of
# the user's does not end up in the picture; the window fills the screen.
DISPLAY=$display XDG_CONFIG_HOME=$home QT_QPA_PLATFORM=xcb \
  build/bin/whitted scenes/seed.json -geometry 1600x1000+0+0 >"$home/editor.log" 2>&1 &
editor_pid=$!

# Wait for the main window ("seed.json — Whitted") to be mapped.
for _ in $(seq 100); do
  kill -0 "$editor_pid" 2>/dev/null || fail "the editor exited: $(cat "$home/editor.log")"
  if DISPLAY=$display xwininfo -root -tree 2>/dev/null | grep -q 'seed.json.*Whitted'; then
    break
  fi
  sleep 0.1
done
DISPLAY=$display xwininfo -root -tree 2>/dev/null | grep -q 'seed.json.*Whitted' ||
  fail "no editor window on $display after 10 s: $(cat "$home/editor.log")"

# The seed scene at 640x480 renders in well under a second; leave time for the
# last frame and the repaint on a busy machine.
sleep 3
kill -0 "$editor_pid" 2>/dev/null || fail "the editor exited: $(cat "$home/editor.log")"

mkdir -p "$(dirname "$out")"
DISPLAY=$display import -window root "$out.tmp.png" || fail "import failed"
mv "$out.tmp.png" "$out"
echo "screenshot: wrote $out"
