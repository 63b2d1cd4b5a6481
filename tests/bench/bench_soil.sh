#!/bin/sh
# Benchmark of the liquefaction scene at its demonstration size (docs/soil.md §6):
# wall time per simulated second split into grains, fluid and rendering.
#   tests/bench/bench_soil.sh [path/to/porelab]     (default build/app/porelab)
# Run 1 renders the demonstration frames (30 fps, 1200x420); run 2 the same frames at 16x16
# with no layers (the scene's logic runs in its on_frame hook, so the frame rate must stay).
# Rendering = difference of the two wall times; fluid = the fluid module's own
# timers (porosity, assembly, factorization, solve, forces, consolidation source) printed by
# the scene; grains = the rest.
set -e
BIN=${1:-build/app/porelab}
SCENE=scenes/soil/liquefaction.lua
OUT=${TMPDIR:-/tmp}/bench_soil
T_END=5.0
run() { # $1 label, rest: options
  label=$1; shift
  start=$(date +%s.%N)
  "$BIN" run "$SCENE" --out "$OUT/$label" "$@" > "$OUT/$label.log" 2>&1 || true
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}
mkdir -p "$OUT"
w_full=$(run frames)
w_none=$(run noframes --size 16x16 --layers none)
fluid=$(grep "fluid time" "$OUT/noframes.log" | sed 's/[^0-9. ]//g' | awk '{s=0; for(i=1;i<=6;i++) s+=$i; print s}')
render=$(echo "$w_full - $w_none" | bc)
grains=$(echo "$w_none - $fluid" | bc)
printf "liquefaction scene, %s s simulated (%s)\n" "$T_END" "$(grep -m1 'steps ' "$OUT/noframes.log" | sed 's/^ *//')"
printf "wall time with frames %.1f s, without %.1f s\n" "$w_full" "$w_none"
printf "per simulated second: grains %.2f s, fluid %.2f s, rendering %.2f s, total %.2f s\n" \
  "$(echo "$grains / $T_END" | bc -l)" "$(echo "$fluid / $T_END" | bc -l)" "$(echo "$render / $T_END" | bc -l)" \
  "$(echo "$w_full / $T_END" | bc -l)"
printf "simulated / wall time: %.3f (with frames), %.3f (without)\n" "$(echo "$T_END / $w_full" | bc -l)" \
  "$(echo "$T_END / $w_none" | bc -l)"
grep "fluid time" "$OUT/noframes.log"
