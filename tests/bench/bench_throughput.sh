#!/bin/bash
# Throughput of the ways porelab runs many or big jobs (docs/scaling.md, "Measured throughput"):
#  1. sweeps through GNU parallel: 8 shaking-table jobs (scenes/grains/shaking_table.lua, 1 s
#     each: amp 4 values x 2 seeds) with 2 at once: jobs per hour of wall time and the CPU each
#     took (from the manifests);
#  2. one big dry scene (bench_throughput_pack.lua: 3,000 discs settling for 1 s) in porelab and,
#     exported with porelab export-lammps, in LAMMPS serial and with mpirun -np 2:
#     particle-steps per second of wall time and per CPU second.
#   tests/bench/bench_throughput.sh [path/to/porelab] [OUTDIR]
# On a shared machine the wall time includes waiting for a core: the CPU rates are the ones to
# compare; the load average at the start and the end is printed beside them.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
exe=${1:-$top/build/app/porelab}
out=${2:-${TMPDIR:-/tmp}/bench_throughput}
rm -rf "$out"
mkdir -p "$out"
cd "$top"
load() { cut -d' ' -f1-3 /proc/loadavg; }
echo "load average at start: $(load)"
timed() { # label command...; prints "wall cpu" (cpu = user + system of the command and its children)
  local label=$1; shift
  /usr/bin/time -f "%e %U %S" -o "$out/$label.time" "$@" > "$out/$label.log" 2>&1 ||
    { cat "$out/$label.log"; echo "bench_throughput: $label failed" >&2; exit 1; }
  awk '{printf "%s %.3f\n", $1, $2 + $3}' "$out/$label.time"
}

echo "== 1. sweep through GNU parallel (8 shaking-table jobs, 1 s simulated each, --jobs 2) =="
if command -v parallel > /dev/null; then
  read -r wall cpu <<< "$(timed sweep "$exe" sweep scenes/grains/shaking_table.lua --grid "amp=0.004,0.008,0.012,0.016" \
    --seeds 1..2 --until 1.0 --run --jobs 2 --out "$out/sweep")"
  jobcpu=$(cat "$out"/sweep/job_*/manifest.json | sed -n 's/.*"cpu_s": \([0-9.e+-]*\).*/\1/p' | awk '{s += $1} END {print s / NR}')
  awk -v w="$wall" -v c="$cpu" -v j="$jobcpu" 'BEGIN {
    printf "sweep: 8 jobs in %.1f s wall (%.0f jobs/h), %.1f s CPU in all, %.2f s CPU per job (manifests)\n", w, 8 * 3600 / w, c, j
    printf "sweep: on 2 free cores: %.0f jobs/h (2 x 3600 / CPU per job)\n", 7200 / j }'
else
  echo "sweep: skipped (GNU parallel, Debian package parallel, is not installed)"
fi

echo "== 2. one big dry scene: porelab, LAMMPS serial, LAMMPS mpirun -np 2 =="
scene=$here/bench_throughput_pack.lua
read -r pw pc <<< "$(timed porelab "$exe" run "$scene" --no-frames -q --out "$out/porelab")"
steps=$(sed -n 's/.*"steps": \([0-9][0-9]*\).*/\1/p' "$out/porelab/manifest.json" | head -1)
n=3000
echo "porelab: $n discs x $steps steps: wall $pw s, CPU $pc s"
"$exe" export-lammps "$scene" --out "$out/lammps" -q
if command -v lmp > /dev/null; then
  cp -r "$out/lammps" "$out/lammps-np2"
  # dumps off for timing: they are not part of the physics
  for d in lammps lammps-np2; do sed -i 's/^\(dump\|dump_modify\|write_dump\|compute\)/# &/; s/^run 0 post no/# &/' "$out/$d/in.lammps"; done
  read -r lw lc <<< "$(cd "$out/lammps" && timed lmp1 lmp -in in.lammps -log log.lammps -screen none)"
  if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
  read -r mw mc <<< "$(cd "$out/lammps-np2" && timed lmp2 mpirun -np 2 --oversubscribe lmp -in in.lammps -log log.lammps -screen none)"
  lsteps=$(sed -n 's/^Loop time of .* for \([0-9]*\) steps.*/\1/p' "$out/lammps/log.lammps" | head -1)
  echo "LAMMPS serial: $n atoms x $lsteps steps: wall $lw s, CPU $lc s ($(grep '^Loop time' "$out/lammps/log.lammps" | head -1))"
  echo "LAMMPS -np 2:  wall $mw s, CPU $mc s ($(grep '^Loop time' "$out/lammps-np2/log.lammps" | head -1))"
  awk -v n=$n -v s="$steps" -v ls="$lsteps" -v pw="$pw" -v pc="$pc" -v lw="$lw" -v lc="$lc" -v mw="$mw" -v mc="$mc" 'BEGIN {
    printf "%-16s %16s %18s\n", "", "particle-steps/s", "particle-steps/CPU s"
    printf "%-16s %16.3g %18.3g\n", "porelab", n * s / pw, n * s / pc
    printf "%-16s %16.3g %18.3g\n", "LAMMPS serial", n * ls / lw, n * ls / lc
    printf "%-16s %16.3g %18.3g\n", "LAMMPS -np 2", n * ls / mw, n * ls / mc }'
else
  echo "LAMMPS: skipped (Debian package lammps, binary lmp, is not installed)"
fi
echo "load average at end: $(load)"
