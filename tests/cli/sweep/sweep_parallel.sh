#!/bin/bash
# A small sweep run through GNU parallel (issue 21): 2 x 2 grid x 2 seeds of the shaking-table
# scene, collected into one CSV, checked; then the same jobs run again (resumed: all skipped),
# one job re-run in series and one through the generated Slurm array script with
# SLURM_ARRAY_TASK_ID set by hand: the same seed gives the same final state hash whether run
# twice, in series or in parallel.
#   sweep_parallel.sh PORELAB SCENE WORKDIR      (exit 77 = skipped: GNU parallel absent)
set -u
exe=$1 scene=$2 dir=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v parallel > /dev/null || { echo "SKIP: GNU parallel (Debian package parallel) is not installed"; exit 77; }
rm -rf "$dir"
mkdir -p "$(dirname "$dir")"
"$exe" sweep "$scene" --grid "amp=0.004,0.012" --grid "freq=4,8" --seeds 1..2 --until 0.8 \
  --out "$dir" --run --jobs 2 --slurm --snakemake > "$dir.log" 2>&1 || { cat "$dir.log"; fail "sweep --run"; }
cat "$dir.log"
grep -q "8 jobs (amp 2 values x freq 2 values x 2 seeds)" "$dir.log" || fail "job count"
"$exe" collect "$dir" --chart nut_rise_mm:amp || fail "collect"
csv=$dir/results.csv
cat "$csv"
grep -q '^# units: amp \[m\]; freq \[Hz\]; nut_rise_mm \[mm\]; peak_accel_g \[g\];' "$csv" || fail "units line"
head=$(grep -v '^#' "$csv" | head -1)
[ "$head" = "run,amp,freq,seed,exit_status,coordination,nut_rise_mm,peak_accel_g,wall_s,cpu_s,steps,state_hash,scene_hash" ] ||
  fail "header: $head"
rows=$(grep -c '^job_' "$csv")
[ "$rows" = 8 ] || fail "$rows rows, expected 8"
# every grid point with both seeds, all finished, every state different
combos=$(grep '^job_' "$csv" | cut -d, -f2,3,4 | sort -u | wc -l)
[ "$combos" = 8 ] || fail "$combos distinct (amp, freq, seed), expected 8"
[ "$(grep '^job_' "$csv" | cut -d, -f5 | sort -u)" = 0 ] || fail "a job did not finish"
[ "$(grep '^job_' "$csv" | cut -d, -f12 | sort -u | wc -l)" = 8 ] || fail "two jobs ended in the same state"
# the peak acceleration the scene reports is A (2 pi f)^2 / g: job 7 is amp 0.012, freq 8
acc=$(grep '^job_0007,' "$csv" | cut -d, -f8)
awk -v a="$acc" 'BEGIN { e = 0.012 * (2 * 3.141592653589793 * 8) ^ 2 / 9.81; exit !(a - e < 1e-9 && e - a < 1e-9) }' ||
  fail "peak_accel_g $acc"
[ -s "$dir/nut_rise_mm_vs_amp.png" ] || fail "chart"
# the chart's own labels and a reference line; a malformed line is refused by name
"$exe" collect "$dir" -o "$dir/labelled.csv" --chart nut_rise_mm:amp --chart-out "$dir/labelled.svg" \
  --xlabel "shaking amplitude A (m)" --ylabel "nut rise (mm)" --line "5:5 mm rise" || fail "collect --line"
# PLplot's svg device writes each character as an entity: decode (perl-base is in every Debian)
txt=$(perl -CS -pe 's/&#x([0-9a-f]+);/chr(hex($1))/ge' "$dir/labelled.svg")
grep -q "shaking amplitude A (m)" <<< "$txt" && grep -q "5 mm rise" <<< "$txt" || fail "labels in the svg"
"$exe" collect "$dir" -o "$dir/bad.csv" --chart nut_rise_mm:amp --line "five:limit" 2> "$dir.errline" && fail "--line five ran"
grep -q "\-\-line must be VALUE:LABEL with a finite number VALUE (got 'five:limit')" "$dir.errline" || { cat "$dir.errline"; fail "--line message"; }
# resumable: nothing left to run
"$exe" sweep "$scene" --grid "amp=0.004,0.012" --grid "freq=4,8" --seeds 1..2 --until 0.8 --out "$dir" --run \
  --jobs 2 > "$dir.log2" 2>&1 || fail "second sweep"
grep -q "8 done, 0 to run" "$dir.log2" || { cat "$dir.log2"; fail "resume"; }
# the same seed again, in series (not through parallel), into another folder: same state hash
h3=$(grep '^job_0003,' "$csv" | cut -d, -f12)
again=$("$exe" run "$scene" --param amp=0.004 --param freq=8 --seed 1 --until 0.8 --no-frames -q --hash \
  --out "$dir-again" | sed -n 's/^state-hash: //p')
echo "job 3 through parallel: $h3, run again in series: $again"
[ -n "$h3" ] && [ "$h3" = "$again" ] || fail "same seed, different state: $h3 vs $again"
# the Slurm array script: valid bash; task 5 run by hand recreates job 5 with the same state
bash -n "$dir/sweep.slurm" || fail "bash -n sweep.slurm"
h5=$(grep '^job_0005,' "$csv" | cut -d, -f12)
rm "$dir/job_0005/manifest.json"
SLURM_ARRAY_TASK_ID=5 bash "$dir/sweep.slurm" || fail "sweep.slurm task 5"
s5=$(sed -n 's/^  "state_hash": "\([0-9a-f]*\)",$/\1/p' "$dir/job_0005/manifest.json")
echo "job 5 through parallel: $h5, through sweep.slurm: $s5"
[ "$h5" = "$s5" ] || fail "slurm task 5: $s5 vs $h5"
SLURM_ARRAY_TASK_ID=9 bash "$dir/sweep.slurm" 2> "$dir.err9" && fail "task 9 of 8 ran"
grep -q "no job 9" "$dir.err9" || fail "task 9 message"
grep -q '^rule run:' "$dir/Snakefile" || fail "Snakefile"
echo "sweep_parallel: all checks passed"
