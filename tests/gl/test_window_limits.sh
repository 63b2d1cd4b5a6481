#!/bin/sh
# The live window keeps the sandbox's CPU limit (issue 13 item 4): a scene whose on_frame hook
# loops for ever (tests/cli/security/cpu_hook.lua) is opened playing with --max-cpu 1; the hook
# must be stopped with the scene's line and the option named (on the terminal and in the
# window), and the window must stay responsive (it still closes on request). The loop in the
# scene file itself is stopped while the window loads it (cli_sec_view_cpu_loop).
#   test_window_limits.sh PORELAB SOURCE_DIR OUT_DIR
set -u
P=$1; SRC=$2; OUT=$3
rm -rf "$OUT"; mkdir -p "$OUT"
XPID=""; VPID=""
trap '[ -n "$VPID" ] && kill $VPID 2>/dev/null; [ -n "$XPID" ] && kill $XPID 2>/dev/null' EXIT
fail() { echo "FAIL: $*"; echo "--- window log:"; cat "$OUT/view.log" 2>/dev/null; exit 1; }
# Xvfb picks a free display itself (-displayfd: no race with other test runs on the machine)
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$OUT/xvfb.display" >/dev/null 2>&1 &
XPID=$!
i=0; while [ ! -s "$OUT/xvfb.display" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
n=$(head -1 "$OUT/xvfb.display")
[ -n "$n" ] || { echo "FAIL: Xvfb did not start"; exit 1; }
export DISPLAY=:$n
cd "$SRC" || exit 1
sc=tests/cli/security/cpu_hook.lua
"$P" view "$sc" --max-cpu 1 --size 320x240 --out "$OUT/v" >"$OUT/view.log" 2>&1 &
VPID=$!
W=$(timeout 20 xdotool search --sync --name "porelab - $sc" | head -1)
[ -n "$W" ] || fail "the window did not appear"
# the hook runs at frame 1 (step 5); 1 s of CPU, then the message (wait at most 30 s)
i=0
while ! grep -q "ran out of CPU time" "$OUT/view.log" && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
grep -Eq "^porelab: stopped: $sc:10: the scene ran out of CPU time: more than 1 s in one call.*--max-cpu" "$OUT/view.log" ||
  fail "the hook's endless loop was not stopped with the scene line and --max-cpu"
kill -0 "$VPID" 2>/dev/null || fail "the window exited instead of showing the error"
xdotool key --window "$W" Escape
i=0; while kill -0 "$VPID" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
kill -0 "$VPID" 2>/dev/null && fail "the window did not close after the stop (Escape)"
VPID=""
echo "ok: $(grep 'ran out of CPU time' "$OUT/view.log")"
