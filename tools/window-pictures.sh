#!/bin/sh
# Regenerates the window pictures of docs/classroom.md for the buoyancy lab under Xvfb:
#   docs/img/classroom_buoyancy.png        the panel at the end of the lab's run (t = 4 s)
#   docs/img/classroom_buoyancy_chart.png  the same moment with the live chart
#   docs/img/classroom_picker.png          the scene picker
#   tools/window-pictures.sh [BUILD_DIR]   (default build; needs Xvfb and xdotool)
# The clicks go to the controls' boxes that the window prints with PORELAB_WINDOW_DEBUG=1.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=${1:-build}
case $B in /*) ;; *) B=$ROOT/$B ;; esac
P=$B/app/porelab CAP=$B/tests/gl_xcapture
[ -x "$P" ] && [ -x "$CAP" ] || { echo "window-pictures.sh: build porelab and gl_xcapture in $B first" >&2; exit 1; }
OUT=$(mktemp -d)
XPID="" VPID=""
trap '[ -n "$VPID" ] && kill $VPID 2>/dev/null; [ -n "$XPID" ] && kill $XPID 2>/dev/null; rm -rf "$OUT"' EXIT
export PORELAB_WINDOW_DEBUG=1 PORELAB_SCENES=$ROOT/scenes
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$OUT/display" >"$OUT/xvfb.log" 2>&1 &
XPID=$!
i=0; while [ ! -s "$OUT/display" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
export DISPLAY=:$(head -1 "$OUT/display")
cd "$ROOT"
"$P" view scenes/lab/buoyancy.lua --paused --size 1120x640 --out "$OUT/v" >"$OUT/view.log" 2>&1 &
VPID=$!
W=$(timeout 20 xdotool search --sync --name "porelab - scenes/lab/buoyancy.lua" | head -1)
i=0; while ! grep -q "porelab view" "$OUT/view.log" && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
sleep 1
ctl() { # clicks the centre of the control KIND [INDEX] last printed by the window
  line=$(grep "^control: $1 ${2:-0} " "$OUT/view.log" | tail -1)
  set -- $line
  xdotool mousemove --window "$W" $((($4 + $6) / 2)) $((($5 + $7) / 2)) click 1
}
ctl play
# the lab pauses by itself at the end of its run (t = 4 s; about 8 s of wall time)
sleep 12
xdotool mousemove --window "$W" 420 400; sleep 0.8
"$CAP" "$W" docs/img/classroom_buoyancy.png
ctl charts; sleep 0.5; xdotool mousemove --window "$W" 420 400; sleep 0.8
"$CAP" "$W" docs/img/classroom_buoyancy_chart.png
ctl charts; sleep 0.3; ctl scenes; sleep 0.8; xdotool mousemove --window "$W" 420 400; sleep 0.5
"$CAP" "$W" docs/img/classroom_picker.png
echo "wrote docs/img/classroom_buoyancy.png, classroom_buoyancy_chart.png, classroom_picker.png"
