#!/usr/bin/env bash
# Runs the simple-shear scene as docs/soil.md §5.4 gives it (default command, frames and all,
# into a temporary folder) and writes what it printed and recorded:
#   docs/data/soil_simple_shear_monotonic.csv, docs/data/soil_simple_shear_cyclic.csv
#   the measured block of docs/soil.md §5.4 (between its simple-shear markers)
#   tools/simple-shear-tables.sh [PORELAB]        (~10 s of CPU on one core)
set -euo pipefail
cd "$(dirname "$0")/.."
EXE=${1:-build/app/porelab}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
t0=$(date +%s.%N)
"$EXE" run scenes/soil/simple_shear.lua --out "$OUT/run" > "$OUT/log" 2>&1 || { cat "$OUT/log"; exit 1; }
t1=$(date +%s.%N)
md="$OUT/block.md"
awk -v wall_total="$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" -v mono="$OUT/run/simple_shear_monotonic.csv" \
    -v cyc="$OUT/run/simple_shear_cyclic.csv" -v dmono=docs/data/soil_simple_shear_monotonic.csv \
    -v dcyc=docs/data/soil_simple_shear_cyclic.csv '
  function m(s) { gsub(/-/, "\342\210\222", s); return s }          # a true minus sign
  function kpa(x) { return m(sprintf("%.1f", x)) }
  function sci(x,   a, d, k, sup) {                                  # 4.8×10⁻⁵
    split(sprintf("%.1e", x), a, "e"); d = a[2] + 0; sup = ""
    split("⁰ ¹ ² ³ ⁴ ⁵ ⁶ ⁷ ⁸ ⁹", S, " ")
    if (d < 0) { sup = "⁻"; d = -d }
    d = sprintf("%d", d); for (k = 1; k <= length(d); k++) sup = sup S[substr(d, k, 1) + 1]
    return a[1] "×10" sup
  }
  # reads a scene CSV (metadata comment, header with units) into col[name] and v[row, k]
  function load(f, pre,   line, n, k, h, a, r) {
    r = 0
    while ((getline line < f) > 0) {
      if (line ~ /^#/) continue
      n = split(line, a, ",")
      if (!h) { for (k = 1; k <= n; k++) { sub(/ \(.*\)$/, "", a[k]); col[pre, a[k]] = k }; h = 1; continue }
      r++; for (k = 1; k <= n; k++) v[pre, r, k] = a[k] + 0
    }
    close(f); rows[pre] = r
  }
  function get(pre, r, name) { return v[pre, r, col[pre, name]] }
  /^simple_shear: .* box / {
    match($0, /box [0-9.]+ x [0-9.]+ mm/); split(substr($0, RSTART + 4, RLENGTH - 7), bx, " x ")
    match($0, /porosity [0-9.]+/); por = substr($0, RSTART + 9, RLENGTH - 9)
    match($0, /e = [0-9.]+/); e = substr($0, RSTART + 4, RLENGTH - 4)
  }
  /^  (monotonic|cyclic): sigma/ { row = $1; sub(/:/, "", row); match($0, /= [0-9.]+ kPa/); sv0[row] = substr($0, RSTART + 2, RLENGTH - 6) + 0 }
  /^    gamma = / { n = ++np["monotonic"]; lab["monotonic", n] = sprintf("%g%%", $3); du["monotonic", n] = $5; dr["monotonic", n] = $7
                    df["monotonic", n] = $9; dh["monotonic", n] = $(NF - 1) }
  /^    cycle [0-9]+ / { n = ++np["cyclic"]; lab["cyclic", n] = "c" $2 " " ($3 == "peak" ? "peak" : "end")
                         i = ($3 == "peak") ? 5 : 4; du["cyclic", n] = $(i); dr["cyclic", n] = $(i + 2); df["cyclic", n] = $(i + 4) }
  /^    whole record/ { match($0, /= [0-9.]+ sigma/); rms[row] = substr($0, RSTART + 2, RLENGTH - 8) }
  /^  steps / { steps = $2; dt = $6; match($0, /, t = [0-9.]+/); tstart = substr($0, RSTART + 6, RLENGTH - 6) }
  /^  wall time/ { sps = $5; sub(/\(/, "", sps) }
  /^  balance error/ { match($0, /\([0-9.e+-]+%/); bal = substr($0, RSTART + 1, RLENGTH - 2) }
  END {
    load(mono, "m"); load(cyc, "c")
    # the undrained lid: largest height change; CV box: sigma_v at the end of the monotonic row
    for (p = 0; p < 2; p++) {
      pre = p ? "c" : "m"; lid[pre] = 0
      for (r = 1; r <= rows[pre]; r++) { x = get(pre, r, "dh_und"); if (x < 0) x = -x; if (x > lid[pre]) lid[pre] = x }
    }
    # the dry servo box: peak of the wall shear stress over sigma_v, and the strain where it is
    pk = 0
    # (the monotonic row holds gamma = 12.5 % from t = 0.025 s to the end of the cyclic row: the
    # peaks are read over the shear itself)
    for (r = 1; r <= rows["m"] && get("m", r, "t") <= 0.0255; r++) { q = get("m", r, "tau_servo") / get("m", r, "sv_servo"); if (q > pk) { pk = q; gpk = get("m", r, "gamma") } }
    tiu0 = get("m", 1, "tau_int_cv"); timax = tiu0
    for (r = 1; r <= rows["m"] && get("m", r, "t") <= 0.0255; r++) if (get("m", r, "tau_int_cv") > timax) { timax = get("m", r, "tau_int_cv"); gti = get("m", r, "gamma") }
    s0 = sv0["monotonic"] * 1e3
    svend = s0 - 1e3 * dr["monotonic", np["monotonic"]]
    printf "Measured with the default command (`tools/simple-shear-tables.sh` runs it and writes this block and the two\n"
    printf "data files): box %s × %s mm after compression, areal porosity %s (e = %s; Tan (1990)'"'"'s loose sample: 8.9 × 6.9 mm,\n", bx[1], bx[2], por, e
    printf "e = 0.261 — our random sample is looser), σ'"'"'_v0 = %.1f kPa.\n\n", sv0["monotonic"]
    hdr = "| monotonic γ |"; sep = "|---|"; r1 = "| Δu undrained (kPa) |"; r2 = "| σ'"'"'_v0 − σ'"'"'_v, dry CV (kPa) |"; r3 = "| difference / σ'"'"'_v0 |"; r4 = "| height change, dry servo |"
    c1 = "monotonic γ"; c2 = "Δu undrained (kPa)"; c3 = "\"σ'"'"'_v0 − σ'"'"'_v, dry CV (kPa)\""; c4 = "difference / σ'"'"'_v0"; c5 = "height change dry servo (%)"
    for (n = 1; n <= np["monotonic"]; n++) {
      hdr = hdr " " lab["monotonic", n] " |"; sep = sep "---|"
      r1 = r1 " " m(du["monotonic", n]) " |"; r2 = r2 " " m(dr["monotonic", n]) " |"; r3 = r3 " " m(df["monotonic", n]) " |"; r4 = r4 " " m(dh["monotonic", n]) "% |"
      c1 = c1 "," lab["monotonic", n]; c2 = c2 "," m(du["monotonic", n]); c3 = c3 "," m(dr["monotonic", n]); c4 = c4 "," m(df["monotonic", n]); c5 = c5 "," m(dh["monotonic", n])
    }
    print hdr; print sep; print r1; print r2; print r3; print r4
    print "# simple shear scene (docs/soil.md §5.4), monotonic row: undrained excess pore pressure vs dry constant-volume drop of vertical effective stress (tools/simple-shear-tables.sh)" > dmono
    print c1 > dmono; print c2 > dmono; print c3 > dmono; print c4 > dmono; print c5 > dmono; close(dmono)
    printf "\nThe table as data: [docs/data/soil_simple_shear_monotonic.csv](data/soil_simple_shear_monotonic.csv).\n\n"
    hdr = "| cyclic ±2.5% |"; sep = "|---|"; r1 = "| Δu (kPa) |"; r2 = "| drop of σ'"'"'_v, CV (kPa) |"; r3 = "| difference / σ'"'"'_v0 |"
    c1 = "cyclic ±2.5%"; c2 = "Δu (kPa)"; c3 = "\"drop of σ'"'"'_v, CV (kPa)\""; c4 = "difference / σ'"'"'_v0"; ru = ""
    for (n = 1; n <= np["cyclic"]; n++) {
      hdr = hdr " " lab["cyclic", n] " |"; sep = sep "---|"
      r1 = r1 " " m(du["cyclic", n]) " |"; r2 = r2 " " m(dr["cyclic", n]) " |"; r3 = r3 " " m(df["cyclic", n]) " |"
      c1 = c1 "," lab["cyclic", n]; c2 = c2 "," m(du["cyclic", n]); c3 = c3 "," m(dr["cyclic", n]); c4 = c4 "," m(df["cyclic", n])
      if (lab["cyclic", n] ~ /end/) ru = ru (ru == "" ? "" : ", ") m(sprintf("%.2f", du["cyclic", n] / sv0["cyclic"]))
    }
    print hdr; print sep; print r1; print r2; print r3
    print "# simple shear scene (docs/soil.md §5.4), cyclic row (±2.5 %): per cycle peak and end (tools/simple-shear-tables.sh)" > dcyc
    print c1 > dcyc; print c2 > dcyc; print c3 > dcyc; print c4 > dcyc; close(dcyc)
    printf "\nThe table as data: [docs/data/soil_simple_shear_cyclic.csv](data/soil_simple_shear_cyclic.csv).\n\n"
    printf "Over the whole record rms(Δu − drop) = %s σ'"'"'_v0 (monotonic) and %s σ'"'"'_v0 (cyclic). The undrained top wall moved\n", rms["monotonic"], rms["cyclic"]
    printf "by at most %s H (monotonic) and %s H (cyclic); the dry servo box changed height by %s%% at 12.5%% strain. At the\n", sci(lid["m"]), sci(lid["c"]), m(dh["monotonic", np["monotonic"]])
    printf "start of the shear the saturated box and its dry constant-volume twin hold σ'"'"'_v = %s and %s kPa and a mean wall\n", kpa(get("m", 1, "sv_und") / 1e3), kpa(get("m", 1, "sv_cv") / 1e3)
    printf "shear stress of %s and %s kPa. The dry servo box'"'"'s wall shear stress is largest at τ/σ'"'"'_v = %.3f (γ = %.1f%%); the\n", kpa(get("m", 1, "tau_und") / 1e3), kpa(get("m", 1, "tau_cv") / 1e3), pk, 100 * gpk
    printf "contact stress τ_xy of the CV sample is %s kPa (%s σ'"'"'_v0) at the start and at most %s kPa (γ = %.1f%%); σ'"'"'_v of the\n", kpa(tiu0 / 1e3), m(sprintf("%.2f", tiu0 / s0)), kpa(timax / 1e3), 100 * gti
    printf "CV box falls to %.0f%% of σ'"'"'_v0 at 12.5%%. Cyclic: r_u = Δu/σ'"'"'_v0 at the cycle ends %s.\n", 100 * svend / s0, ru
    printf "The pressure samples along the top wall read %.1f%% more than the water'"'"'s force on the lid per unit width of the\n", 100 * (get("m", 1, "u_top") / get("m", 1, "u_lid") - 1)
    printf "box (the lid is 0.3 mm narrower than the box).\n"
    printf "The run took %.1f s here (%.0f grain steps of %s s to prepare, %s to shear, %s steps/s while shearing and drawing;\n", wall_total, tstart / dt, dt, steps, sps
    printf "energy balance error %s%% of the energy exchanged).\n", bal
  }' "$OUT/log" > "$md"
awk -v md="$md" '
  /<!-- simple-shear:begin/ { print; while ((getline line < md) > 0) print line; skip = 1; next }
  /<!-- simple-shear:end/ { skip = 0 }
  !skip { print }' docs/soil.md > docs/soil.md.tmp && mv docs/soil.md.tmp docs/soil.md
cat "$md"
echo "simple-shear-tables: wrote docs/data/soil_simple_shear_monotonic.csv, docs/data/soil_simple_shear_cyclic.csv and the block in docs/soil.md §5.4"
