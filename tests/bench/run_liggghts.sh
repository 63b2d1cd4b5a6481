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
liggghts -var RST poly.restart -var NSTEP "$steps" -var BW 0.2 -log none -in settle2d_bench.in > bench.log
loop=$(grep -o 'Loop time of [0-9.e+-]*' bench.log | awk '{print $4}')
atoms=$(grep -o 'with [0-9]* atoms' bench.log | tail -1 | awk '{print $2}')
cs=$(awk '/^ *[0-9]+ +[0-9]+ +[0-9.e+-]+ +[0-9]+ *$/ {c=$4} END {print c}' bench.log)
python3 - "$loop" "$atoms" "$steps" "$cs" <<'PY'
import sys
loop, atoms, steps, cs = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
print(f"liggghts: {atoms} discs, {cs/2:.0f} contacts, {steps} steps in {loop:.3f} s: {atoms*steps/loop:.3e} particle-steps/s")
print(f"liggghts,{atoms},{cs/2:.0f},{steps},{loop:.4f},{atoms*steps/loop:.6e}")
PY
