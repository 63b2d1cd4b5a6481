#!/bin/sh
# The live window under Xvfb, driven by xdotool (label gl):
#  1. keys (hide HUD, single frames, screenshot): the screenshot and the window's own pixels
#     (captured with XGetImage) equal the headless GL render of the same state (PSNR >= 40 dB;
#     measured: identical, both llvmpipe);
#  2. rewind: step, screenshot, rewind one frame, step again, screenshot: identical pictures;
#  3. mouse wheel zoom: the window shows the zoomed screenshot, which differs from the
#     unzoomed render; 'z' restores the fitted view;
#  4. a scene parameter (up arrow on the selected parameter) changes what happens;
#  5. dragging a grain on the spring changes what happens; a right click fixes it in place;
#  6. the scene file is watched: a syntax error is reported and the previous scene stays,
#     fixing the file reloads it;
#  7. the other keys: space plays and pauses, +/- change the steps per frame, layer keys,
#     colouring (c), fluid field (f), colour range ([ ]), a drag on empty space pans and z
#     restores, the help (h) is drawn in the window, r restarts at t = 0 (= headless);
#  8. the control panel lies outside the scene's area; its buttons and toggles work by mouse;
#  9. the live chart (render.live) updates while the scene plays, outside the scene's area;
# 10. the scene picker lists the shipped scenes and opens one by a click.
# The scene is the buoyancy lab on the Darcy model (scenes/lab/buoyancy_darcy.lua), which has a
# pressure field for the fluid keys to change.
#   test_window_xvfb.sh PORELAB GL_PSNR GL_XCAPTURE SOURCE_DIR OUT_DIR
set -u
unset PORELAB_GL_SAMPLES PORELAB_WINDOW_SAMPLES # the goldens and thresholds are for the defaults
export PORELAB_WINDOW_DEBUG=1 # the window prints its camera with each screenshot (for clicks)
export PORELAB_SCENES="$4/scenes" # the picker lists the source tree's scenes (the scene runs from a copy)
P=$1; PSNR=$2; CAP=$3; SRC=$4; OUT=$5
rm -rf "$OUT"; mkdir -p "$OUT"
XPID=""; VPID=""
cleanup() {
  [ -n "$VPID" ] && kill "$VPID" 2>/dev/null
  [ -n "$XPID" ] && kill "$XPID" 2>/dev/null
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; echo "--- window log:"; cat "$OUT/view.log" 2>/dev/null; exit 1; }

# Xvfb picks a free display itself (-displayfd: no race with other test runs on the machine)
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$OUT/xvfb.display" >"$OUT/xvfb.log" 2>&1 &
XPID=$!
i=0; while [ ! -s "$OUT/xvfb.display" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
n=$(head -1 "$OUT/xvfb.display")
[ -n "$n" ] || { echo "FAIL: Xvfb did not start"; exit 1; }
export DISPLAY=:$n

cp "$SRC/scenes/lab/buoyancy_darcy.lua" "$OUT/scene.lua"
"$P" view "$OUT/scene.lua" --paused --size 640x480 --out "$OUT/v" >"$OUT/view.log" 2>&1 &
VPID=$!
W=$(timeout 20 xdotool search --sync --name "porelab - $OUT/scene.lua" | head -1)
[ -n "$W" ] || fail "the window did not appear"
# the start line follows the window's creation (GL set up): wait for it
i=0; while ! grep -q "porelab view" "$OUT/view.log" && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
grep -q "porelab view" "$OUT/view.log" || fail "no start line"

# waits until the log has N screenshot lines; prints the last one's time
shots() { grep -c '^screenshot:' "$OUT/view.log"; }
wait_shots() {
  i=0; while [ "$(shots)" -lt "$1" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
  [ "$(shots)" -ge "$1" ] || fail "screenshot $1 was not written"
  sleep 0.3 # the next frame is on screen
}
shot_time() { grep '^screenshot:' "$OUT/view.log" | sed -n "${1}p" | sed 's/.*(t = \([^ ]*\) s.*/\1/'; }
key() { xdotool key --window "$W" --delay 60 "$@"; }

# 1. keys; the window and the screenshot against the headless render
key i s s s p
wait_shots 1
"$CAP" "$W" "$OUT/window_1.png" || fail "capture"
T=$(shot_time 1)
"$P" still "$OUT/scene.lua" --at "$T" --size 640x480 -o "$OUT/headless_1.png" --renderer gl \
  --out "$OUT/h" -q || fail "headless still"
p1=$("$PSNR" "$OUT/v/screenshot_000.png" "$OUT/headless_1.png" 40) || fail "screenshot vs headless $p1 dB"
p2=$("$PSNR" "$OUT/window_1.png" "$OUT/headless_1.png" 40) || fail "window vs headless $p2 dB"
echo "t = $T s: screenshot vs headless $p1 dB, window pixels vs headless $p2 dB"

# 2. rewind determinism
key s p
wait_shots 2
key Left s p
wait_shots 3
grep -q '^rewind: ' "$OUT/view.log" || fail "no rewind"
p3=$("$PSNR" "$OUT/v/screenshot_001.png" "$OUT/v/screenshot_002.png" 200) || fail "rewound replay differs ($p3 dB)"
echo "rewind one frame and replay: $p3 dB (identical)"

# 3. wheel zoom at the window centre, then back
xdotool mousemove --window "$W" 320 240
xdotool click --window "$W" 4 click --window "$W" 4 click --window "$W" 4
sleep 0.3
key p
wait_shots 4
"$CAP" "$W" "$OUT/window_zoom.png" || fail "capture"
p4=$("$PSNR" "$OUT/window_zoom.png" "$OUT/v/screenshot_003.png" 40) || fail "zoomed window vs screenshot $p4 dB"
if p5=$("$PSNR" "$OUT/v/screenshot_003.png" "$OUT/v/screenshot_002.png" 30); then fail "zoom changed nothing ($p5 dB)"; fi
key z p
wait_shots 5
p6=$("$PSNR" "$OUT/v/screenshot_004.png" "$OUT/v/screenshot_002.png" 200) || fail "z did not restore the view ($p6 dB)"
echo "zoom: window = screenshot ($p4 dB), differs from unzoomed ($p5 dB); z restores ($p6 dB)"

# 4. a parameter: the wood block (first parameter) made denser than water sinks
key Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up Up
key s s s s s s s s s s s s s s s p
wait_shots 6
T=$(shot_time 6)
"$P" still "$OUT/scene.lua" --at "$T" --size 640x480 -o "$OUT/headless_6.png" --renderer gl \
  --out "$OUT/h" -q || fail "headless still 6"
if p7=$("$PSNR" "$OUT/v/screenshot_005.png" "$OUT/headless_6.png" 40); then
  fail "raising the wood density changed nothing ($p7 dB)"
fi
echo "wood density 600 -> 3000 kg/m3: differs from the unchanged scene ($p7 dB)"

# 5. grab the wood block (a spring to the cursor) and pull it down into the water while
#    stepping; then fix it (right click) where it is and step on: it stays put.
cam=$(grep '^camera:' "$OUT/view.log" | tail -1)
set -- $cam
S=$3; CX=$5; CY=$6; PX=$8; PY=$9
topx() { echo "$1 $2" | awk -v s="$S" -v cx="$CX" -v cy="$CY" -v px="$PX" -v py="$PY" \
  '{ printf "%d %d", (($1 - cx) * s + px), (py - ($2 - cy) * s) }'; }
key R
sleep 0.3
key s s s s s s s s s s s s s s s s s s s s s s s s s s s s s s p
wait_shots 7
xy=$(topx 0.08 0.28); set -- $xy; X0=$1; Y0=$2
xy=$(topx 0.08 0.12); set -- $xy; X1=$1; Y1=$2
xdotool mousemove --window "$W" "$X0" "$Y0" mousedown 1
sleep 0.2
xdotool mousemove --window "$W" "$X1" "$Y1"
sleep 0.3
key s s s s s s s s s s s s s s s
xdotool mouseup 1
key p
wait_shots 8
T=$(shot_time 8)
"$P" still "$OUT/scene.lua" --at "$T" --size 640x480 -o "$OUT/headless_8.png" --renderer gl \
  --out "$OUT/h" -q || fail "headless still 8"
if p9=$("$PSNR" "$OUT/v/screenshot_007.png" "$OUT/headless_8.png" 35); then
  fail "dragging the wood block changed nothing ($p9 dB)"
fi
xdotool mousemove --window "$W" "$X1" "$Y1" click 3
key s s s s s s s s s s p
wait_shots 9
key s s s s s s s s s s p
wait_shots 10
# around the block (its half size is 0.035 x 0.02 m; 0.05 m box)
xy=$(topx 0.03 0.17); set -- $xy; BX=$1; BY=$2
BW=$(echo "$S" | awk '{ printf "%d", 0.10 * $1 }'); BH=$(echo "$S" | awk '{ printf "%d", 0.10 * $1 }')
p10=$("$PSNR" "$OUT/v/screenshot_008.png" "$OUT/v/screenshot_009.png" 40 $BX $BY $BW $BH) || \
  fail "the fixed block moved ($p10 dB in the box $BX $BY $BW $BH)"
echo "grab: the dragged block differs from the untouched run ($p9 dB); fixed by right click, it stays ($p10 dB)"

# 6. the file watch: a syntax error keeps the scene, a fix reloads it
sleep 1.1 # a new modification time
echo "this is not lua (" >>"$OUT/scene.lua"
i=0; while ! grep -q '^reload: failed' "$OUT/view.log" && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
grep -q '^reload: failed' "$OUT/view.log" || fail "the syntax error was not reported"
grep '^reload: failed' "$OUT/view.log" | grep -q "scene.lua:" || fail "the error does not name the file"
key p
wait_shots 11
p8=$("$PSNR" "$OUT/v/screenshot_010.png" "$OUT/v/screenshot_009.png" 200) || fail "the previous scene did not stay ($p8 dB)"
sleep 1.1
cp "$SRC/scenes/lab/buoyancy_darcy.lua" "$OUT/scene.lua"
i=0; while ! grep -q '^reload: ok' "$OUT/view.log" && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
grep -q '^reload: ok' "$OUT/view.log" || fail "fixing the file did not reload it"
echo "file watch: syntax error reported, previous scene kept ($p8 dB), fix reloaded"

# 7. the other keys (the scene just reloaded, paused)
differs() { # screenshot numbers a b: fail unless they differ
  if q=$("$PSNR" "$OUT/v/screenshot_$(printf %03d "$1").png" "$OUT/v/screenshot_$(printf %03d "$2").png" 60); then
    fail "$3 changed nothing ($q dB)"; fi
}
# one step per frame first (- halves the steps per frame), so that playing for a moment
# cannot reach the scene's end time (the window pauses there by itself)
key minus minus minus minus minus minus minus minus minus
key s p
wait_shots 12
T0=$(shot_time 12)
key space; sleep 0.5; key space p
wait_shots 13
T1=$(shot_time 13)
awk -v a="$T0" -v b="$T1" 'BEGIN { exit !(b > a) }' || fail "space did not play (t = $T0 -> $T1 s)"
key plus plus minus
i=0; while [ "$(grep -c '^speed:' "$OUT/view.log")" -lt 12 ] && [ $i -lt 30 ]; do sleep 0.1; i=$((i + 1)); done
sp() { grep '^speed:' "$OUT/view.log" | sed -n "$1p" | awk '{print $2}'; }
[ "$(sp 9)" = 1 ] || fail "- did not slow down to 1 step per frame ($(sp 9))"
[ "$(sp 10)" = 2 ] && [ "$(sp 11)" = 4 ] && [ "$(sp 12)" = 2 ] || \
  fail "+ + - did not give 2, 4, 2 steps per frame ($(sp 10), $(sp 11), $(sp 12))"
key 3 p; wait_shots 14; differs 13 14 "the pressure layer key (3)"; key 3
key c p; wait_shots 15; differs 13 15 "colouring by speed (c)"; key c c
key f p; wait_shots 16; differs 13 16 "the fluid field key (f)"; key f f
key bracketleft bracketleft p; wait_shots 17; differs 13 17 "a narrower colour range ([)"; key a
xdotool mousemove --window "$W" 30 30 mousedown 1
sleep 0.2
xdotool mousemove --window "$W" 90 70
sleep 0.2
xdotool mouseup 1
key p; wait_shots 18; differs 13 18 "dragging empty space (pan)"
key z p; wait_shots 19
q=$("$PSNR" "$OUT/v/screenshot_012.png" "$OUT/v/screenshot_018.png" 200) || fail "z after the pan did not restore the view ($q dB)"
key i; sleep 0.4
"$CAP" "$W" "$OUT/window_hud.png" || fail "capture"
key h; sleep 0.4
"$CAP" "$W" "$OUT/window_help.png" || fail "capture"
key h i
if q=$("$PSNR" "$OUT/window_hud.png" "$OUT/window_help.png" 60); then fail "h drew no help ($q dB)"; fi
key r p; wait_shots 20
[ "$(shot_time 20)" = 0 ] || fail "r did not restart at t = 0 ($(shot_time 20) s)"
"$P" still "$OUT/scene.lua" --at 0 --size 640x480 -o "$OUT/headless_0.png" --renderer gl \
  --out "$OUT/h" -q || fail "headless still at 0"
q=$("$PSNR" "$OUT/v/screenshot_019.png" "$OUT/headless_0.png" 40) || fail "restart vs headless at 0 ($q dB)"
echo "keys: space played t = $T0 -> $T1 s; - and + halve and double the steps per frame; 3, c, f, [ change the picture; pan and z; help drawn; r restarts ($q dB vs headless)"

# 8. the control panel: outside the scene's area, and its controls work with the mouse.
#    The panel is the right strip of width P = clamp(W / 4, 220, 320) = 220 px at 640 px. With
#    the HUD on (i), the window's pixels left of the panel equal the screenshot (the scene
#    without any HUD), the cursor over the scene: no HUD pixel lies in the scene's area.
PX0=420
key i
xdotool mousemove --window "$W" 200 200; sleep 0.2
key p; wait_shots 21
"$CAP" "$W" "$OUT/window_panel.png" || fail "capture with the panel"
q=$("$PSNR" "$OUT/window_panel.png" "$OUT/v/screenshot_020.png" 60 0 0 $PX0 480) ||
  fail "a HUD pixel inside the scene's area ($q dB over x < $PX0)"
if q2=$("$PSNR" "$OUT/window_panel.png" "$OUT/v/screenshot_020.png" 60); then
  fail "the control panel is not drawn ($q2 dB over the whole window)"; fi
# the controls' boxes come from the window's log (PORELAB_WINDOW_DEBUG: "control: KIND INDEX
# x0 y0 x1 y1 [NAME]", printed when the panel's layout changes); ctl KIND [INDEX] clicks the
# centre of the last one printed
ctl() {
  line=$(grep "^control: $1 ${2:-0} " "$OUT/view.log" | tail -1)
  [ -n "$line" ] || fail "no control $1 ${2:-0} in the window's log"
  set -- $line
  xdotool mousemove --window "$W" $((($4 + $6) / 2)) $((($5 + $7) / 2)) click 1
}
t_a=$(shot_time 21)
ctl step; sleep 0.3
key p; wait_shots 22
t_b=$(shot_time 22)
[ "$t_a" != "$t_b" ] || fail "the one-step button did not step (t = $t_a s)"
# the play button plays, a second click pauses
ctl play; sleep 0.6
ctl play; sleep 0.2
key p; wait_shots 23
t_c=$(shot_time 23)
awk -v a="$t_b" -v b="$t_c" 'BEGIN { exit !(b > a) }' || fail "the play button did not play ($t_b -> $t_c s)"
# the first layer box ("grains and bodies") hides the bodies; a second click shows them
ctl layer 0; sleep 0.3
key p; wait_shots 24
if q3=$("$PSNR" "$OUT/v/screenshot_023.png" "$OUT/v/screenshot_022.png" 60); then
  fail "the bodies toggle changed nothing ($q3 dB)"; fi
ctl layer 0; sleep 0.2
# the "back 1 s" button rewinds one second (to t = 0 if the run is younger): the window's log
# reports the rewind and its time, below the time before
ctl rewind 1; sleep 0.5
t_r=$(grep '^rewind: ' "$OUT/view.log" | tail -1 | sed 's/.*(t = \([^ ]*\) s).*/\1/')
awk -v a="$t_c" -v b="$t_r" 'BEGIN { exit !(b != "" && b < a && b >= a - 1.0 - 1e-6) }' ||
  fail "the back 1 s button did not rewind one second ($t_c -> $t_r s)"
# the restart button: back to t = 0
ctl restart; sleep 0.3
key p; wait_shots 25
[ "$(shot_time 25)" = 0 ] || fail "the restart button did not restart ($(shot_time 25) s)"
echo "panel: no HUD pixel in the scene's area ($q dB), panel drawn; step ($t_a -> $t_b s), play ($t_b -> $t_c s), layer toggle, back 1 s ($t_c -> $t_r s), restart work by mouse"

# 9. the live chart (the scene's render.live: the blocks' heights): the charts button shows it
#    in the panel; while the scene plays the chart changes; no HUD pixel in the scene's area
ctl charts; sleep 0.3
xdotool mousemove --window "$W" 200 200; sleep 0.2
"$CAP" "$W" "$OUT/window_chart_1.png" || fail "capture with the chart"
ctl play; sleep 1.0; ctl play; sleep 0.3
xdotool mousemove --window "$W" 200 200; sleep 0.2
key p; wait_shots 26
"$CAP" "$W" "$OUT/window_chart_2.png" || fail "capture with the chart"
q4=$("$PSNR" "$OUT/window_chart_2.png" "$OUT/v/screenshot_025.png" 60 0 0 $PX0 480) ||
  fail "a HUD pixel inside the scene's area with the chart shown ($q4 dB over x < $PX0)"
PW=$((640 - PX0))
if q5=$("$PSNR" "$OUT/window_chart_1.png" "$OUT/window_chart_2.png" 60 $PX0 115 $PW 365); then
  fail "the live chart did not change while the scene played ($q5 dB)"; fi
echo "live chart: updates while playing ($q5 dB between two moments), no HUD pixel in the scene's area ($q4 dB)"

# 10. the scene picker: the scenes button lists the shipped scenes (lab/ first) with their
#     descriptions; a click on one opens it (window title, log); no HUD pixel in the scene's area
ctl scenes; sleep 0.4
grep -q "^control: pick .* lab/buoyancy$" "$OUT/view.log" || fail "the picker does not list lab/buoyancy"
grep -q "^control: pick .* lab/floating_block$" "$OUT/view.log" || fail "the picker does not list lab/floating_block"
"$CAP" "$W" "$OUT/window_picker.png" || fail "capture with the picker"
line=$(grep "^control: pick .* lab/floating_block$" "$OUT/view.log" | tail -1)
set -- $line
xdotool mousemove --window "$W" $((($4 + $6) / 2)) $((($5 + $7) / 2)) click 1
i=0; while ! grep -q '^open: ' "$OUT/view.log" && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
grep -q '^open: .*lab/floating_block.lua' "$OUT/view.log" || fail "clicking lab/floating_block did not open it"
sleep 0.3
xdotool getwindowname "$W" | grep -q 'lab/floating_block.lua' || fail "the window title does not name the new scene"
xdotool mousemove --window "$W" 200 200; sleep 0.2
key p; wait_shots 27
"$CAP" "$W" "$OUT/window_opened.png" || fail "capture after opening"
q6=$("$PSNR" "$OUT/window_opened.png" "$OUT/v/screenshot_026.png" 60 0 0 $PX0 480) ||
  fail "a HUD pixel inside the scene's area after opening a scene ($q6 dB over x < $PX0)"
key i p; wait_shots 28 # the scene alone (HUD off) against the headless render at the same time
T=$(shot_time 28)
"$P" still "$SRC/scenes/lab/floating_block.lua" --at "$T" --size 640x480 -o "$OUT/headless_fb.png" --renderer gl \
  --out "$OUT/h" -q || fail "headless still of the opened scene"
q7=$("$PSNR" "$OUT/v/screenshot_027.png" "$OUT/headless_fb.png" 40) || fail "opened scene vs headless ($q7 dB)"
key i
echo "picker: lists the scenes, opens lab/floating_block (= headless, $q7 dB), no HUD pixel in the scene's area ($q6 dB)"

key q
i=0; while kill -0 "$VPID" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
kill -0 "$VPID" 2>/dev/null && fail "q did not close the window"
wait "$VPID" || fail "the window exited with an error"
VPID=""
echo ok
