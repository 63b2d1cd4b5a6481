#!/bin/sh
# Side-by-side Taylor-Hood P2/P1 lid-driven cavity at Re = 100 (stationary Navier-Stokes, Stokes
# start, Newton to 1e-10): porelab (tests/bench/bench_navier_stokes --cavity-p2 H, gmsh mesh of
# size H) against FreeFEM++ (square(n, n) with about as many triangles, UMFPACK) in the same run
# on the same machine. Both report CPU time for assembly (Jacobian and residual, every Newton
# iteration) and for factorisation + solve; ratios > 1 mean porelab is faster.
#   tests/bench/run_freefem_ns.sh [path/to/bench_navier_stokes] [H]
# Needs FreeFem++ (Debian package freefem++).
set -e
BENCH=${1:-build/tests/bench_navier_stokes}
H=${2:-0.02}
FF=$(command -v FreeFem++-nw || command -v FreeFem++ || true)
[ -x "$BENCH" ] || { echo "run_freefem_ns.sh: no benchmark at $BENCH (build the target bench_navier_stokes)"; exit 1; }
[ -n "$FF" ] || { echo "run_freefem_ns.sh: FreeFem++ not found (Debian package freefem++)"; exit 1; }
OUT=$("$BENCH" --cavity-p2 "$H")
PL=$(echo "$OUT" | grep '^FF ') || { echo "$OUT"; exit 1; }
NT=$(echo "$PL" | awk '{ print $3 }')
N=$(awk -v t="$NT" 'BEGIN { printf "%d", sqrt(t / 2) + 0.5 }')
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cat > "$TMP/cavity.edp" <<EDP
// Lid-driven cavity, Re = 100, Taylor-Hood P2/P1, Newton from the Stokes solution.
int n = $N;
mesh Th = square(n, n);
fespace Xh(Th, [P2, P2, P1]);
fespace Vh(Th, P2);
real nu = 1. / 100.;
real eps = 1e-10; // fixes the pressure constant of the closed cavity
Xh [u1, u2, p], [v1, v2, q], [d1, d2, dd];
Vh w1, w2;
macro Grad(u) [dx(u), dy(u)] //
macro Div(a, b) (dx(a) + dy(b)) //
varf vStokes([a1, a2, ap], [v1, v2, q]) = int2d(Th)(nu * (Grad(a1)' * Grad(v1) + Grad(a2)' * Grad(v2))
    - ap * Div(v1, v2) - q * Div(a1, a2) - eps * ap * q)
    + on(3, a1 = 1, a2 = 0) + on(1, 2, 4, a1 = 0, a2 = 0);
varf vJ([a1, a2, ap], [v1, v2, q]) = int2d(Th)(nu * (Grad(a1)' * Grad(v1) + Grad(a2)' * Grad(v2))
    + (a1 * dx(u1) + a2 * dy(u1) + u1 * dx(a1) + u2 * dy(a1)) * v1
    + (a1 * dx(u2) + a2 * dy(u2) + u1 * dx(a2) + u2 * dy(a2)) * v2
    - ap * Div(v1, v2) - q * Div(a1, a2) - eps * ap * q)
    + on(1, 2, 3, 4, a1 = 0, a2 = 0);
varf vR([a1, a2, ap], [v1, v2, q]) = int2d(Th)(nu * (Grad(u1)' * Grad(v1) + Grad(u2)' * Grad(v2))
    + (u1 * dx(u1) + u2 * dy(u1)) * v1 + (u1 * dx(u2) + u2 * dy(u2)) * v2
    - p * Div(v1, v2) - q * Div(u1, u2) - eps * p * q)
    + on(1, 2, 3, 4, a1 = 0, a2 = 0);
real tasm = 0, tfs = 0, t0;
t0 = clock();
matrix S = vStokes(Xh, Xh, solver = UMFPACK);
real[int] b = vStokes(0, Xh);
tasm += clock() - t0;
t0 = clock();
u1[] = S^-1 * b;
tfs += clock() - t0;
int it, nf = 1;
for (it = 0; it < 25; it++) {
    t0 = clock();
    matrix J = vJ(Xh, Xh);
    real[int] r = vR(0, Xh);
    tasm += clock() - t0;
    t0 = clock();
    set(J, solver = UMFPACK);
    real[int] d = J^-1 * r;
    tfs += clock() - t0;
    nf++;
    u1[] -= d;
    d1[] = d;
    w1 = d1;
    w2 = d2;
    if (max(w1[].linfty, w2[].linfty) <= 1e-10 * (1 + u1[].linfty)) break;
}
real umin = 1e9, vmin = 1e9, vmax = -1e9;
for (int i = 1; i < 400; i++) {
    real s = i / 400.;
    umin = min(umin, u1(0.5, s));
    vmin = min(vmin, u2(s, 0.5));
    vmax = max(vmax, u2(s, 0.5));
}
cout << "FF triangles " << Th.nt << " unknowns " << Xh.ndof << " factorisations " << nf << " assemble " << tasm
     << " factor+solve " << tfs << " umin " << umin << " vmin " << vmin << " vmax " << vmax << endl;
EDP
FO=$("$FF" -nw -v 0 "$TMP/cavity.edp" 2>&1 | grep '^FF ') || { echo "run_freefem_ns.sh: FreeFem++ failed"; exit 1; }
echo "porelab   (gmsh, h = $H): $(echo "$PL" | cut -c4-)"
echo "FreeFEM++ (square($N, $N)): $(echo "$FO" | cut -c4-)"
echo "$PL $FO" | awk '{
  # fields: FF triangles T unknowns U factorisations F assemble A factor+solve S ... twice
  for (i = 1; i <= NF; i++) {
    if ($i == "FF") k++;
    if ($i == "unknowns") u[k] = $(i + 1); if ($i == "factorisations") f[k] = $(i + 1);
    if ($i == "assemble") a[k] = $(i + 1); if ($i == "factor+solve") s[k] = $(i + 1);
    if ($i == "umin") um[k] = $(i + 1); if ($i == "vmin") vn[k] = $(i + 1); if ($i == "vmax") vx[k] = $(i + 1)
  }
  printf "unknowns: porelab %d, FreeFEM++ %d; factorisations (Stokes + Newton): %d, %d\n", u[1], u[2], f[1], f[2];
  printf "assembly: porelab %.4f s (%.2f ms per 1000 unknowns and factorisation), FreeFEM++ %.4f s (%.2f) -> ratio %.1f\n",
    a[1], 1e6 * a[1] / u[1] / f[1], a[2], 1e6 * a[2] / u[2] / f[2], (a[2] / u[2] / f[2]) / (a[1] / u[1] / f[1]);
  printf "factorisation + solve: porelab %.4f s (%.2f ms per 1000 unknowns and factorisation), FreeFEM++ %.4f s (%.2f) -> ratio %.2f\n",
    s[1], 1e6 * s[1] / u[1] / f[1], s[2], 1e6 * s[2] / u[2] / f[2], (s[2] / u[2] / f[2]) / (s[1] / u[1] / f[1]);
  printf "centreline extremes u_min, v_min, v_max: porelab %.5f %.5f %.5f, FreeFEM++ %.5f %.5f %.5f (Ghia 1982: -0.21090 -0.24533 0.17527)\n",
    um[1], vn[1], vx[1], um[2], vn[2], vx[2] }'
