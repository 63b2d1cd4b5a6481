#!/bin/sh
# Benchmark of the liquefaction scene at its demonstration size (docs/soil.md §6):
# time per simulated second split into grains, fluid and rendering.
#   tests/bench/bench_soil.sh [path/to/porelab]     (default build/app/porelab)
# Run 1 renders the demonstration frames (30 fps, 1200x420); run 2 the same frames at 16x16
# with no layers (the scene's logic runs in its on_frame hook, so the frame rate must stay).
# Rendering = difference of the two runs; fluid = the fluid module's own timers (porosity,
# assembly, factorization, solve, forces, consolidation source) printed by the scene; grains =
# the rest. Both wall time and CPU time (user + system) are measured: on a shared machine the
# wall time includes waiting for a core, so the fluid timers (wall clock) are scaled by
# CPU / wall of the same run to give the CPU split.
set -e
BIN=${1:-build/app/porelab}
SCENE=scenes/soil/liquefaction.lua
OUT=${TMPDIR:-/tmp}/bench_soil
T_END=6.2   # the scene's run.t_end
run() { # $1 label, rest: options; prints "wall cpu"
  label=$1; shift
  /usr/bin/time -f "%e %U %S" -o "$OUT/$label.time" "$BIN" run "$SCENE" --out "$OUT/$label" "$@" \
    > "$OUT/$label.log" 2>&1 || true
  awk '{printf "%s %.2f\n", $1, $2 + $3}' "$OUT/$label.time"
}
mkdir -p "$OUT"
set -- $(run frames)
w_full=$1; c_full=$2
set -- $(run noframes --size 16x16 --layers none)
w_none=$1; c_none=$2
fl() { grep "fluid time" "$OUT/noframes.log" | sed 's/[^0-9. ]//g' | awk -v k="$1" '{print $k}'; }
fluid=$(grep "fluid time" "$OUT/noframes.log" | sed 's/[^0-9. ]//g' | awk '{s=0; for(i=1;i<=6;i++) s+=$i; print s}')
scale=$(echo "$c_none / $w_none" | bc -l)
printf "liquefaction scene, %s s simulated, %s\n" "$T_END" "$BIN"
printf "wall time with frames %.1f s, without %.1f s; CPU time with frames %.1f s, without %.1f s\n" \
  "$w_full" "$w_none" "$c_full" "$c_none"
printf "per simulated second (wall): grains %.2f s, fluid %.2f s (porosity %.2f, forces %.2f), rendering %.2f s, total %.2f s\n" \
  "$(echo "($w_none - $fluid) / $T_END" | bc -l)" "$(echo "$fluid / $T_END" | bc -l)" \
  "$(echo "$(fl 1) / $T_END" | bc -l)" "$(echo "$(fl 5) / $T_END" | bc -l)" \
  "$(echo "($w_full - $w_none) / $T_END" | bc -l)" "$(echo "$w_full / $T_END" | bc -l)"
printf "per simulated second (CPU):  grains %.2f s, fluid %.2f s (porosity %.2f, forces %.2f), rendering %.2f s, total %.2f s\n" \
  "$(echo "($c_none - $fluid * $scale) / $T_END" | bc -l)" "$(echo "$fluid * $scale / $T_END" | bc -l)" \
  "$(echo "$(fl 1) * $scale / $T_END" | bc -l)" "$(echo "$(fl 5) * $scale / $T_END" | bc -l)" \
  "$(echo "($c_full - $c_none) / $T_END" | bc -l)" "$(echo "$c_full / $T_END" | bc -l)"
printf "simulated / wall time: %.3f (with frames), %.3f (without); simulated / CPU time: %.3f, %.3f\n" \
  "$(echo "$T_END / $w_full" | bc -l)" "$(echo "$T_END / $w_none" | bc -l)" \
  "$(echo "$T_END / $c_full" | bc -l)" "$(echo "$T_END / $c_none" | bc -l)"
grep "fluid time" "$OUT/noframes.log"
