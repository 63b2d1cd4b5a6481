#!/bin/sh
# Regenerates the figures reproduced from the source publications into docs/figures/ (PNG, ready to
# commit), building what is needed first:
#   klosek1997-fig4-2-dam-mesh.png        Klosek 1997 Fig. 4-2: dam flow, meshed regions A, B, C
#   klosek1997-fig4-3-dam.png             Fig. 4-3: equipotential lines under the dam
#   klosek1997-fig4-6-buoyancy-half.png   Fig. 4-6: rho_p = rho_f / 2 floats half submerged
#   klosek1997-fig4-7-buoyancy-equal.png  Fig. 4-7: rho_p = rho_f rests just under the surface
#   klosek1997-fig4-8-buoyancy-heavy.png  Fig. 4-8: rho_p > rho_f sinks to the bottom
#   klosek1997-fig4-1{0,1,2}-wave.png     Figs. 4-10 to 4-12: pressure wave, FE against erfc
#   tan1990-fig2-13-five-discs.png     Tan 1990 Fig. 2.13(a): contact forces of five discs
#   polygon-packing-force-chains.png   force chains in a settled packing of 400 polygons
# Scenes: scenes/figures/; the wave charts: tests/render/wave_figures.c. About half a
# minute on 2 cores after the build. See docs/validation.md (Figures) and docs/rendering.md.
#   usage: tools/figures.sh [BUILD_DIR]     (default: build in the source tree)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
case $build in /*) ;; *) build=$(pwd)/$build ;; esac
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target porelab wave_figures >/dev/null
porelab=$build/app/porelab
out=$root/docs/figures
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
cd "$root"

still() { # scene (under scenes/figures/, or a path ending in .lua) time file layers...
  scene=$1 at=$2 file=$3
  shift 3
  case $scene in *.lua) path=$scene; scene=$(basename "$scene" .lua) ;; *) path=scenes/figures/$scene.lua ;; esac
  "$porelab" still "$path" --at "$at" -o "$out/$file" --out "$tmp/$scene" \
    --quiet "$@"
  echo "wrote docs/figures/$file"
}

# Klosek 1997 §4.1: flow under a dam (one static solve)
still dam_flow 0 klosek1997-fig4-2-dam-mesh.png \
  --layers bodies,mesh,pressure,velocity,colorbar,title,overlay
still dam_flow 0 klosek1997-fig4-3-dam.png --layers bodies,isolines,title,overlay
# Klosek 1997 §4.2: end states of the buoyancy problem (the heavy particle lands at t = 53 s)
still buoyancy_half 150 klosek1997-fig4-6-buoyancy-half.png
still buoyancy_equal 150 klosek1997-fig4-7-buoyancy-equal.png
still buoyancy_heavy 53 klosek1997-fig4-8-buoyancy-heavy.png
# Klosek 1997 §4.3: pressure wave, finite elements (4 to 64 elements) against erfc
"$build/tests/wave_figures" "$out" | sed "s|$root/||"
# Tan 1990 §2.2.5.2: five discs settled under gravity, contact forces against Table 2.2
still scenes/five_discs.lua 5 tan1990-fig2-13-five-discs.png
# force chains of a settled polygon packing (the grains of Mueller et al. 2020)
still polygon_packing 1.5 polygon-packing-force-chains.png
