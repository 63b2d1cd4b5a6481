#!/bin/sh
# Macro properties of the bonded rock against its micro parameters (docs/rock.md, "Calibration"):
# runs the UCS and Brazilian scenes over a grid of the bond stiffness ratio k_t/k_n and the
# strength ratio R_t/R_n (porelab sweep, GNU parallel), collects them (porelab collect), prints
# one markdown table, charts sigma_t against R_t/R_n at k_t/k_n = 0.5, and runs the UCS scene
# over R_n and k_n to chart the scaling of the UCS with R_n and of E with k_n.
#   tools/rock_calibration.sh [OUT]        (default out/rock_calibration; resumes when re-run)
# Needs build/app/porelab and GNU parallel. 24 runs of 5-15 s of CPU each.
set -eu
P=${PORELAB:-build/app/porelab}
OUT=${1:-out/rock_calibration}
GRID="--grid kt_ratio=0.25,0.5,1 --grid rt_ratio=1,2,4"
$P sweep scenes/rock/ucs.lua $GRID --grid width=60 --run --out "$OUT/ucs" > /dev/null
$P sweep scenes/rock/brazilian.lua $GRID --grid size=80 --run --out "$OUT/brazilian" > /dev/null
$P collect "$OUT/ucs" > /dev/null
$P collect "$OUT/brazilian" > /dev/null
$P sweep scenes/rock/ucs.lua --grid rn=1.25e4,2.5e4,5e4 --grid width=60 --run --out "$OUT/ucs_rn" > /dev/null
$P sweep scenes/rock/ucs.lua --grid kn=1e10,2e10,4e10 --grid width=60 --run --out "$OUT/ucs_kn" > /dev/null
$P collect "$OUT/ucs_rn" --chart ucs_MPa:rn --chart-out "$OUT/rock_ucs_vs_rn.png" \
  --title "UCS against the bond tensile strength R#dn#u" --xlabel "bond tensile strength R#dn#u (N/m)" \
  --ylabel "unconfined compressive strength (MPa)" > /dev/null
$P collect "$OUT/ucs_kn" --chart E_GPa:kn --chart-out "$OUT/rock_E_vs_kn.png" \
  --title "Young's modulus against the bond stiffness k#dn#u" --xlabel "bond stiffness k#dn#u (N/m)" \
  --ylabel "Young's modulus E (GPa)" > /dev/null
# sigma_t at k_t/k_n = 0.5 (jobs 4-6 of the grid: rt_ratio 1, 2, 4)
$P collect "$OUT/brazilian/job_0004" "$OUT/brazilian/job_0005" "$OUT/brazilian/job_0006" -o "$OUT/bz_kt05.csv" \
  --chart sigma_t_MPa:rt_ratio --chart-out "$OUT/rock_sigma_t_vs_strength_ratio.png" \
  --title "Brazilian strength against the bond strength ratio (k#dt#u/k#dn#u = 0.5)" \
  --xlabel "bond strength ratio R#dt#u/R#dn#u" --ylabel "tensile strength #gs#dt#u (MPa)" > /dev/null
# rows (by column name, the CSV header after the '#' lines): kt_ratio, rt_ratio, E, nu, UCS | sigma_t
col() { grep -v '^#' "$1" | head -1 | tr ',' '\n' | grep -n -x "$2" | head -1 | cut -d: -f1; }
U="$OUT/ucs/results.csv"; B="$OUT/brazilian/results.csv"
uk=$(col "$U" kt_ratio); ur=$(col "$U" rt_ratio); ue=$(col "$U" E_GPa); un=$(col "$U" nu); uu=$(col "$U" ucs_MPa)
bk=$(col "$B" kt_ratio); br=$(col "$B" rt_ratio); bs=$(col "$B" sigma_t_MPa)
echo "| k_t/k_n | R_t/R_n | E (GPa) | ν | UCS (MPa) | σ_t (MPa) | UCS/σ_t |"
echo "|---|---|---|---|---|---|---|"
grep -v '^#' "$B" | tail -n +2 | awk -F, -v k="$bk" -v r="$br" -v s="$bs" '{print $k "," $r "," $s}' > "$OUT/.bz_rows"
grep -v '^#' "$U" | tail -n +2 | awk -F, -v k="$uk" -v r="$ur" -v e="$ue" -v n="$un" -v u="$uu" -v bz="$OUT/.bz_rows" '
  BEGIN { while ((getline line < bz) > 0) { split(line, a, ","); st[a[1] "," a[2]] = a[3] } }
  { key = $k "," $r; t = st[key];
    printf "| %s | %s | %.1f | %.2f | %.1f | %s | %s |\n", $k, $r, $e, $n, $u,
           (t == "" ? "-" : sprintf("%.2f", t)), (t == "" ? "-" : sprintf("%.1f", $u / t)) }'
rm -f "$OUT/.bz_rows"
for d in ucs_rn ucs_kn; do
  c=$(grep -v '^#' "$OUT/$d/results.csv" | head -1 | tr ',' '\n' | grep -n -x "${d#ucs_}" | head -1 | cut -d: -f1)
  grep -v '^#' "$OUT/$d/results.csv" | tail -n +2 | awk -F, -v c="$c" -v e="$ue" -v u="$uu" -v n="$un" -v name="${d#ucs_}" \
    '{ printf "%s = %g: E = %.2f GPa, nu = %.3f, UCS = %.2f MPa\n", name, $c, $e, $n, $u }'
done
