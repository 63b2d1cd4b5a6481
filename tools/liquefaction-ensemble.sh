#!/bin/bash
# Regenerates the liquefaction ensemble (docs/scaling.md, "The liquefaction ensemble";
# docs/soil.md, "Liquefaction ensemble") from scratch with one porelab sweep and its chart:
#   12 runs of scenes/soil/liquefaction.lua: amp_mm = 3.5 (0.35 g) and 5 (0.5 g) x run seeds
#   0..5 (seed 0 is the scene as written, rain seed 11; the others rain other packings),
#   through GNU parallel, then porelab collect.
# Writes docs/data/liquefaction-ensemble.csv (one row per run), docs/figures/
# liquefaction-ensemble.png (peak r_u against the amplitude: every run, mean, +-1 s.d.) and
# docs/data/liquefaction-ensemble.md (the table docs/scaling.md and docs/soil.md show, also pasted
# between their markers). About 12 x 60 s of CPU on one core.
#   tools/liquefaction-ensemble.sh                    (from the repository; build/app/porelab)
#   PORELAB=path/to/porelab JOBS=2 SEEDS=0..5 tools/liquefaction-ensemble.sh
# The runs go to out/liquefaction-ensemble/ (OUT=...); a re-run resumes: finished runs with the
# same inputs are skipped, so after a change to the scene or the build every run is redone.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
exe=${PORELAB:-$root/build/app/porelab}
jobs=${JOBS:-2}
seeds=${SEEDS:-0..5}
out=${OUT:-out/liquefaction-ensemble}
csv=docs/data/liquefaction-ensemble.csv
png=docs/figures/liquefaction-ensemble.png
md=docs/data/liquefaction-ensemble.md
[ -x "$exe" ] || { echo "liquefaction-ensemble: no porelab at $exe (build it, or set PORELAB)" >&2; exit 1; }
command -v parallel > /dev/null || { echo "liquefaction-ensemble: GNU parallel is needed (Debian package parallel)" >&2; exit 1; }
mkdir -p docs/data docs/figures

nice -n 10 "$exe" sweep scenes/soil/liquefaction.lua --grid "amp_mm=3.5,5" --seeds "$seeds" --run --jobs "$jobs" \
  --out "$out"
"$exe" collect "$out" -o "$csv" --chart ru_peak:amp_mm --chart-out "$png" \
  --title "Liquefaction: peak excess pore pressure ratio, loose saturated tank" \
  --xlabel "shaking amplitude (mm)" --ylabel "peak r#du#u in the free field" \
  --line "0.9:liquefied: r#du#u > 0.9"
# paths in the CSV relative to the repository (the jobs ran with absolute ones)
sed -i "s|$root/||g" "$csv"

# the markdown table: one row per run, then mean +- s.d. per amplitude
awk -F, '
  /^#/ { next }
  !head { for (i = 1; i <= NF; i++) col[$i] = i; head = 1; next }
  function v(name) { return (name in col) ? $(col[name]) : "" }
  {
    n++; amp[n] = v("amp_mm"); seed[n] = v("seed"); st[n] = v("exit_status")
    split("ru_peak ru_end dense_ru_peak settlement_mm dry_settlement_mm dense_settlement_mm pipe_rise_mm dry_pipe_rise_mm cpu_s", keys, " ")
    for (k = 1; k <= 9; k++) val[n, k] = v(keys[k])
    crit[n] = v("criteria_met")
  }
  END {
    print "| amplitude | seed | loose wet r_u: peak during shaking / left at the end (0.8 s after the shaking) | dense wet r_u peak | building settlement loose wet / dry / dense, mm | pipe rise loose wet / dry, mm | criteria met | CPU s |"
    print "|---|---|---|---|---|---|---|---|"
    for (i = 1; i <= n; i++) {
      if (st[i] != 0) { printf "| %.2f g | %s | run failed (exit %s) | | | | | |\n", amp[i] / 10, seed[i], st[i]; continue }
      printf "| %.2f g | %s | %.2f / %.2f | %.2f | %.1f / %.1f / %.1f | %+.1f / %+.1f | %s | %.0f |\n", amp[i] / 10, seed[i],
             val[i, 1], val[i, 2], val[i, 3], val[i, 4], val[i, 5], val[i, 6], val[i, 7], val[i, 8],
             (crit[i] == "true" || crit[i] == 1) ? "yes" : "no", val[i, 9]
      a = amp[i]; cnt[a]++; if (!(a in seen)) { seen[a] = 1; order[++na] = a }
      for (k = 1; k <= 8; k++) { s[a, k] += val[i, k]; q[a, k] += val[i, k] * val[i, k] }
    }
    for (j = 1; j <= na; j++) {
      a = order[j]; m = cnt[a]
      for (k = 1; k <= 8; k++) {
        mu[k] = s[a, k] / m; var = m > 1 ? (q[a, k] - m * mu[k] * mu[k]) / (m - 1) : 0
        sd[k] = var > 0 ? sqrt(var) : 0
      }
      printf "| **%.2f g, mean ± s.d. of %d** | | %.2f ± %.2f / %.2f ± %.2f | %.2f ± %.2f | %.1f ± %.1f / %.1f ± %.1f / %.1f ± %.1f | %+.1f ± %.1f / %+.1f ± %.1f | | |\n",
             a / 10, m, mu[1], sd[1], mu[2], sd[2], mu[3], sd[3], mu[4], sd[4], mu[5], sd[5], mu[6], sd[6], mu[7], sd[7], mu[8], sd[8]
    }
  }' "$csv" > "$md"
# into docs/scaling.md and docs/soil.md between their markers
for doc in docs/scaling.md docs/soil.md; do
awk -v md="$md" '
  /<!-- liquefaction-ensemble:begin/ { print; while ((getline line < md) > 0) print line; skip = 1; next }
  /<!-- liquefaction-ensemble:end/ { skip = 0 }
  !skip { print }' "$doc" > "$doc.tmp" && mv "$doc.tmp" "$doc"
done
cat "$md"
echo "liquefaction-ensemble: wrote $csv, $png, $md and the tables in docs/scaling.md and docs/soil.md"
