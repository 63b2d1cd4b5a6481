#!/usr/bin/env bash
# Runs every benchmark on this machine and writes CSV under build/bench-results/ plus a
# summary on stdout. Peers (LIGGGHTS, FreeFEM++) are installed from Debian when missing and
# run in the same session, so the ratios compare like with like.
#   tests/bench/run_all.sh            # everything (about 15 minutes on 2 cores)
#   tests/bench/run_all.sh dem        # only the grain engine against LIGGGHTS
#   tests/bench/run_all.sh solid      # only the finite-element solid (rewrites docs/solids.md's tables)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
build=${PL_BUILD:-$top/build}
out=$build/bench-results
mkdir -p "$out"
what=${1:-all}
cmake --build "$build" -j2 --target bench_dem >/dev/null

if [ "$what" = all ] || [ "$what" = dem ]; then
  csv=$out/dem.csv
  echo "label,particles,contacts,steps,cpu_seconds,wall_seconds,particle_steps_per_cpu_s,contacts_per_cpu_s,bytes_per_particle,threads,particle_steps_per_wall_s" > "$csv"
  echo "== grains: porelab (one core, then two threads: same state hash) =="
  "$build/tests/bench_dem" --label discs_5978 --csv "$csv" --hash
  "$build/tests/bench_dem" --label discs_5978_threads2 --threads 2 --csv "$csv" --hash
  "$build/tests/bench_dem" --label discs_5978_no_energy --no-energy --csv "$csv"
  "$build/tests/bench_dem" --label discs_20k --columns 98 --rows 204 --settle 0.8 --settle-dt 2e-5 --settle-damping 30 --steps 5000 --csv "$csv" --hash
  "$build/tests/bench_dem" --label discs_20k_threads2 --threads 2 --columns 98 --rows 204 --settle 0.8 --settle-dt 2e-5 --settle-damping 30 --steps 5000 --csv "$csv" --hash
  "$build/tests/bench_dem" --label discs_200k --columns 1000 --rows 200 --settle 0.3 --settle-dt 5e-5 --settle-damping 30 --steps 1000 --csv "$csv"
  "$build/tests/bench_dem" --label polygons_5k --polygons --columns 49 --rows 102 --settle 0.3 --settle-dt 2e-5 --steps 2000 --csv "$csv" --hash
  "$build/tests/bench_dem" --label polygons_5k_threads2 --threads 2 --polygons --columns 49 --rows 102 --settle 0.3 --settle-dt 2e-5 --steps 2000 --csv "$csv" --hash
  echo "== grains: LIGGGHTS (same packing, same core count) =="
  "$here/run_liggghts.sh" 20000 | tee "$out/liggghts.txt"
fi
if [ "$what" = all ] || [ "$what" = fluid ]; then
  if [ -x "$build/tests/bench_fluid" ]; then
    echo "== fluid: porelab and FreeFEM++ =="
    "$here/run_freefem.sh" "$build/tests/bench_fluid" | tee "$out/fluid.txt"
  fi
  if [ -x "$build/tests/bench_water" ]; then
    echo "== still water: hydrostatic against Darcy on the buoyancy lab =="
    echo "scene,model,steps,us_per_step,water_us_per_step" > "$out/water.csv"
    "$build/tests/bench_water" 20000 5 "$out/water.csv" | tee "$out/water.txt"
  fi
fi
if [ "$what" = all ] || [ "$what" = render ]; then
  if [ -x "$build/tests/bench_render" ]; then
    echo "== rendering =="
    "$build/tests/bench_render" | tee "$out/render.txt"
  fi
fi
if [ "$what" = all ] || [ "$what" = solid ]; then
  cmake --build "$build" -j2 --target bench_solid >/dev/null
  if [ -x "$build/tests/bench_solid" ]; then
    echo "== finite-element solid: element-steps/s, FIC against plain; coupled cutting cost =="
    (cd "$out" && "$build/tests/bench_solid" 20 2000 "$out/solid.md") | tee "$out/solid.txt"
    # the tables of docs/solids.md ("Cost") are this run's own output
    awk -v md="$out/solid.md" '
      /<!-- bench_solid:begin/ { print; while ((getline line < md) > 0) print line; skip = 1; next }
      /<!-- bench_solid:end/ { skip = 0 }
      !skip { print }' "$top/docs/solids.md" > "$top/docs/solids.md.tmp" && mv "$top/docs/solids.md.tmp" "$top/docs/solids.md"
  fi
fi
echo "results in $out"
