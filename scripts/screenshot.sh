#!/usr/bin/env bash
# Takes the README's screenshots of the editor: starts Xvfb on a free display,
# opens build/bin/whitted on a scene (scenes/seed.json unless --scene), waits for
# the render to finish, and writes the whole screen to docs/images/editor.png or
# OUT.png. With --precision-view it first opens the Float vs Double dock (its
# shortcut, Ctrl+Shift+F, sent with xdotool). With --tradeoff-view it opens the
# Trade-off dock, pins the Final preset's render, renders the other presets and
# two sample counts against it, then runs Measure and waits
# TRADEOFF_MEASURE_SECONDS (150 unless set) for it. With --moving it selects
# the three balls (a click, two Shift+clicks), presses G and moves the pointer
# up, and takes the picture during the move. With --ray-tree X Y it Ctrl+clicks
# the window's point X,Y, which opens the Ray Tree dock on that pixel, then
# clicks the window's point RAY_TREE_ROW ("X Y", if set): a row of the dock,
# whose ray the view then draws highlighted. With --quality-final it renders to
# Final (Ctrl+3), shows the Render tab and waits QUALITY_FINAL_SECONDS (25
# unless set) for the render. Safe to re-run.
# Needs xvfb, x11-utils (xwininfo) and imagemagick (import), and xdotool for
# --precision-view, --tradeoff-view, --moving and --ray-tree. Build first (scripts/setup.sh).
# Usage: scripts/screenshot.sh [--scene SCENE.json] [--precision-view | --tradeoff-view |
#                               --moving | --ray-tree X Y | --quality-final] [OUT.png]
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=docs/images/editor.png
scene=scenes/seed.json
precision_view=
tradeoff_view=
moving=
ray_tree=
quality_final=
while [[ $# -gt 0 ]]; do
  case $1 in
    --scene) scene=$2; shift 2 ;;
    --precision-view) precision_view=1; shift ;;
    --tradeoff-view) tradeoff_view=1; shift ;;
    --moving) moving=1; shift ;;
    --ray-tree) ray_tree="$2 $3"; shift 3 ;;
    --quality-final) quality_final=1; shift ;;
    *) out=$1; shift ;;
  esac
done
title=$(basename "$scene")
size=1600x1000x24

fail() {
  echo "screenshot: $*" >&2
  exit 1
}

[[ -x build/bin/whitted ]] || fail "build/bin/whitted is not built (run scripts/setup.sh)"
tools="Xvfb xwininfo import${precision_view:+ xdotool}${tradeoff_view:+ xdotool}${moving:+ xdotool}${ray_tree:+ xdotool}${quality_final:+ xdotool}"
for tool in $tools; do
  command -v "$tool" >/dev/null 2>&1 || fail "$tool not found (apt-get install xvfb x11-utils imagemagick xdotool)"
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
# the user's does not end up in the picture; the window fills the screen. A
# fresh data directory too: the editor is killed at the end, and its recovery
# copy of unsaved edits (--tradeoff-view makes some) must not reach the user's
# next start, nor a user's recovery offer this picture.
DISPLAY=$display XDG_CONFIG_HOME=$home XDG_DATA_HOME=$home QT_QPA_PLATFORM=xcb \
  build/bin/whitted "$scene" -geometry 1600x1000+0+0 >"$home/editor.log" 2>&1 &
editor_pid=$!

# Wait for the main window ("seed.json — Whitted") to be mapped.
window_shown() {
  DISPLAY=$display xwininfo -root -tree 2>/dev/null | grep -qF "$title"
}
for _ in $(seq 100); do
  kill -0 "$editor_pid" 2>/dev/null || fail "the editor exited: $(cat "$home/editor.log")"
  if window_shown; then
    break
  fi
  sleep 0.1
done
window_shown ||
  fail "no editor window on $display after 10 s: $(cat "$home/editor.log")"

if [[ -n "$precision_view" ]]; then
  sleep 1
  # No window manager runs on Xvfb: give the window the focus directly.
  id=$(DISPLAY=$display xdotool search --name "$title" | head -n 1)
  DISPLAY=$display xdotool windowfocus --sync "$id" key --clearmodifiers ctrl+shift+f ||
    fail "could not send Ctrl+Shift+F to the editor"
fi

if [[ -n "$tradeoff_view" ]]; then
  sleep 1
  id=$(DISPLAY=$display xdotool search --name "$title" | head -n 1)
  keys() {
    DISPLAY=$display xdotool windowfocus --sync "$id" key --clearmodifiers "$@" ||
      fail "could not send $* to the editor"
  }
  # Click at a point of the 1600x1000 window (no window manager: the window is at 0,0).
  click() {
    DISPLAY=$display xdotool mousemove --sync "$1" "$2" click 1 ||
      fail "could not click at $1,$2"
  }
  # The dock; the Final preset (Ctrl+3) pinned; then Draft and Preview (Ctrl+1,
  # Ctrl+2) and two sample counts typed into the Render tab's field, each a
  # point against it. They come first, while the renders have the cores to
  # themselves, so their times compare with Measure's.
  keys ctrl+shift+t ctrl+3
  sleep 6
  keys ctrl+shift+p ctrl+1
  sleep 2
  keys ctrl+2
  sleep 2
  click 1371 90 # the Render tab
  for spp in 16 32; do
    click 1440 320 # the samples field
    keys ctrl+a
    DISPLAY=$display xdotool type --delay 50 "$spp"
    keys Return
    sleep 4
  done
  # Then Measure: its question is a window of its own, answered with Return.
  keys ctrl+shift+m
  box=
  for _ in $(seq 50); do
    box=$(DISPLAY=$display xdotool search --name "Measure Trade-off" | head -n 1) && break
    sleep 0.1
  done
  [[ -n "$box" ]] || fail "no Measure question on $display"
  DISPLAY=$display xdotool windowfocus --sync "$box" key Return
  sleep "${TRADEOFF_MEASURE_SECONDS:-150}"
fi

if [[ -n "$moving" ]]; then
  sleep 2
  id=$(DISPLAY=$display xdotool search --name "$title" | head -n 1)
  DISPLAY=$display xdotool windowfocus --sync "$id" ||
    fail "could not focus the editor"
  # The seed's purple, white and blue balls in the 1600x1000 window at 0,0.
  at() {
    DISPLAY=$display xdotool mousemove --sync "$1" "$2" ||
      fail "could not move the pointer to $1,$2"
  }
  at 559 478
  DISPLAY=$display xdotool click 1
  for ball in "727 467" "867 493"; do
    at $ball
    DISPLAY=$display xdotool keydown shift click 1 keyup shift
  done
  sleep 1
  DISPLAY=$display xdotool key g
  for step in $(seq 1 12); do
    at 867 $((493 - 6 * step))
    sleep 0.05
  done
fi

if [[ -n "$ray_tree" ]]; then
  sleep 2
  id=$(DISPLAY=$display xdotool search --name "$title" | head -n 1)
  DISPLAY=$display xdotool windowfocus --sync "$id" ||
    fail "could not focus the editor"
  # shellcheck disable=SC2086 # X and Y, two words
  DISPLAY=$display xdotool mousemove --sync $ray_tree keydown ctrl click 1 keyup ctrl ||
    fail "could not Ctrl+click at $ray_tree"
  sleep 2
  if [[ -n "${RAY_TREE_ROW:-}" ]]; then
    # shellcheck disable=SC2086 # X and Y, two words
    DISPLAY=$display xdotool mousemove --sync $RAY_TREE_ROW click 1 ||
      fail "could not click the row at $RAY_TREE_ROW"
  fi
fi

if [[ -n "$quality_final" ]]; then
  sleep 2
  id=$(DISPLAY=$display xdotool search --name "$title" | head -n 1)
  DISPLAY=$display xdotool windowfocus --sync "$id" key --clearmodifiers ctrl+3 ||
    fail "could not send Ctrl+3 to the editor"
  sleep 1
  # The Render tab of the 1600x1000 window at 0,0.
  DISPLAY=$display xdotool mousemove --sync 1314 90 click 1 ||
    fail "could not click the Render tab"
  sleep "${QUALITY_FINAL_SECONDS:-25}"
fi

# The example scenes at 640x480 render in well under a second, and compare in
# float and double at 480x360 in a fraction of one; leave time for the last
# frame and the repaint on a busy machine.
sleep 3
kill -0 "$editor_pid" 2>/dev/null || fail "the editor exited: $(cat "$home/editor.log")"

mkdir -p "$(dirname "$out")"
DISPLAY=$display import -window root "$out.tmp.png" || fail "import failed"
mv "$out.tmp.png" "$out"
echo "screenshot: wrote $out"
