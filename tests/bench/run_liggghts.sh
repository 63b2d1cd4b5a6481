#!/usr/bin/env bash
# Runs the LIGGGHTS baseline of ../shared/bench/liggghts on this machine and prints
# particle-steps per second. Installs the Debian package liggghts when missing.
# The packing preparation takes about 7 minutes on one core; its restart file is cached in
# $PL_BENCH_CACHE (default build/bench-cache).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
shared=${PL_SHARED:-$top/../shared}
cache=${PL_BENCH_CACHE:-$top/build/bench-cache}
mkdir -p "$cache"
if ! command -v liggghts >/dev/null; then
  ${SUDO:-} apt-get install -y -qq liggghts >/dev/null || { echo "liggghts: cannot install the Debian package" >&2; exit 1; }
fi
cp "$shared/bench/liggghts/"*.in "$cache/"
cd "$cache"
if [ ! -f poly.restart ]; then
  echo "LIGGGHTS: preparing the settled packing (about 7 minutes)..." >&2
  liggghts -var BW 0.2 -var BH 0.5 -var IW 0.198 -var IH 0.49 -var NSTEP 400000 -var RST poly.restart -log none -in prep_poly.in > prep.log
fi
steps=${1:-20000}
command -v /usr/bin/time >/dev/null || ${SUDO:-} apt-get install -y -qq time >/dev/null
# CPU seconds of the loop = CPU of the whole run minus CPU of the same run with 0 steps
# (reading the restart, setup): comparable with porelab's CPU-time figures on a busy machine.
/usr/bin/time -f "%U %S" -o time_full.txt \
  liggghts -var RST poly.restart -var NSTEP "$steps" -var BW 0.2 -log none -in settle2d_bench.in > bench.log
/usr/bin/time -f "%U %S" -o time_zero.txt \
  liggghts -var RST poly.restart -var NSTEP 0 -var BW 0.2 -log none -in settle2d_bench.in > bench0.log
loop=$(grep -o 'Loop time of [0-9.e+-]*' bench.log | awk '{print $4}')
atoms=$(grep -o 'with [0-9]* atoms' bench.log | tail -1 | awk '{print $2}')
cs=$(awk '/^ *[0-9]+ +[0-9]+ +[0-9.e+-]+ +[0-9]+ *$/ {c=$4} END {print c}' bench.log)
python3 - "$loop" "$atoms" "$steps" "$cs" "$(tail -1 time_full.txt)" "$(tail -1 time_zero.txt)" <<'PY'
import sys
loop, atoms, steps, cs = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
full = sum(map(float, sys.argv[5].split())); zero = sum(map(float, sys.argv[6].split()))
cpu = full - zero
print(f"liggghts: {atoms} discs, {cs/2:.0f} contacts, {steps} steps in {cpu:.3f} s CPU ({loop:.3f} s wall loop time): "
      f"{atoms*steps/cpu:.3e} particle-steps/s per CPU second ({atoms*steps/loop:.3e} per wall second)")
print(f"liggghts,{atoms},{cs/2:.0f},{steps},{cpu:.4f},{loop:.4f},{atoms*steps/cpu:.6e}")
PY
