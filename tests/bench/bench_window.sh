#!/bin/sh
# Window frame rate under Xvfb (GLX on llvmpipe): porelab view on tests/bench/scenes/
# window_grains.lua at 1280x720 (bodies, force chains, pressure field), 10,000 and 50,000
# grains; paused (drawing only) and playing (--speed 1: one engine step per drawn frame).
# vsync off (PORELAB_VSYNC=0). The window's sample count comes from PORELAB_WINDOW_SAMPLES
# (default 1, as headless). Prints one line per case; CSV to $OUT/bench_window.csv.
#   bench_window.sh PORELAB SOURCE_DIR OUT_DIR [seconds per case, default 8]
set -u
P=$1; SRC=$2; OUT=$3; SECS=${4:-8}
mkdir -p "$OUT"
n=81
while [ -e /tmp/.X11-unix/X$n ] || [ -e /tmp/.X$n-lock ]; do n=$((n + 1)); done
Xvfb :$n -screen 0 1400x800x24 -nolisten tcp >/dev/null 2>&1 &
XPID=$!
trap 'kill $XPID 2>/dev/null' EXIT
export DISPLAY=:$n PORELAB_VSYNC=0
sleep 1
echo "grains,mode,samples,frames,seconds,fps" >"$OUT/bench_window.csv"
for N in 10000 50000; do
  sed "s/^local N = 10000/local N = $N/" "$SRC/tests/bench/scenes/window_grains.lua" >"$OUT/grains_$N.lua"
  for mode in paused playing; do
    flag=--paused; [ $mode = playing ] && flag="--speed 1"
    "$P" view "$OUT/grains_$N.lua" $flag --steps 1000000 --out "$OUT/w" >"$OUT/view_${N}_$mode.log" 2>&1 &
    VPID=$!
    W=$(timeout 120 xdotool search --sync --name "porelab - $OUT/grains_$N.lua" | head -1)
    sleep "$SECS"
    xdotool key --window "$W" q
    wait $VPID
    line=$(grep "frames in" "$OUT/view_${N}_$mode.log")
    frames=$(echo "$line" | sed 's/.*: \([0-9]*\) frames in \([0-9.]*\) s (mean \([0-9.]*\).*/\1,\2,\3/')
    echo "$N grains, $mode: $line"
    echo "$N,$mode,${PORELAB_WINDOW_SAMPLES:-1},$frames" >>"$OUT/bench_window.csv"
  done
done
