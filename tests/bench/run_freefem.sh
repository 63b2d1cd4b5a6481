#!/bin/sh
# Side-by-side P1 Darcy solve: porelab (tests/bench/bench_fluid) against FreeFEM++ on a mesh with
# about the same number of nodes, in the same run on the same machine (/work/shared/bench/README.md).
#   tests/bench/run_freefem.sh [path/to/bench_fluid] [cells]
# FreeFEM's square(2n, 2n) has (2n + 1)^2 nodes; n is chosen to match porelab's
# (cells + 1)^2 + cells^2 nodes. Ratios > 1 mean porelab is faster.
set -e
BENCH=${1:-build/tests/bench_fluid}
CELLS=${2:-100}
EDP=${PL_FREEFEM_EDP:-/work/shared/bench/freefem/darcy_p1.edp}
FF=$(command -v FreeFem++-nw || command -v FreeFem++ || true)
[ -x "$BENCH" ] || { echo "run_freefem.sh: no benchmark at $BENCH (build the target bench_fluid)"; exit 1; }
[ -n "$FF" ] || { echo "run_freefem.sh: FreeFem++ not found (Debian package freefem++)"; exit 1; }
[ -f "$EDP" ] || { echo "run_freefem.sh: $EDP not found (set PL_FREEFEM_EDP)"; exit 1; }
OUT=$("$BENCH" "$CELLS")
echo "$OUT" | grep -v '^CSV'
CSV=$(echo "$OUT" | grep '^CSV [0-9]' | sed 's/^CSV //')
NODES=$(echo "$CSV" | cut -d, -f1)
N=$(awk -v n="$NODES" 'BEGIN { printf "%d", (sqrt(n) - 1) / 2 + 0.5 }')
TMP=$(mktemp -d)
sed "s/NN/$N/" "$EDP" > "$TMP/darcy.edp"
FFOUT=$("$FF" -v 0 "$TMP/darcy.edp" 2>&1 | grep '^nodes')
rm -rf "$TMP"
echo "FreeFEM++ square($((2 * N)), $((2 * N))): $FFOUT"
echo "$CSV" "$FFOUT" | awk -F'[ ,]+' '{
  setup = $9; asm = $10; fs = $11; rs = $12;
  for (i = 13; i <= NF; i++) { if ($i == "assemble") fa = $(i + 1); if ($i == "factor+solve") ffs = $(i + 1);
                               if ($i == "resolve") frs = $(i + 1); if ($i == "nodes") fn = $(i + 1) }
  printf "nodes: porelab %d, FreeFEM++ %d\n", $1, fn;
  printf "assembly: porelab %.4f s (values into the kept pattern), %.4f s with mesh + pattern + analysis; FreeFEM++ %.4f s -> ratio %.1f (%.1f)\n", asm, asm + setup, fa, fa / asm, fa / (asm + setup);
  printf "factorization + solve: porelab %.4f s, FreeFEM++ %.4f s -> ratio %.2f\n", fs, ffs, ffs / fs;
  printf "re-solve with the stored factor: porelab %.4f s, FreeFEM++ %.4f s -> ratio %.2f\n", rs, frs, frs / rs }'
