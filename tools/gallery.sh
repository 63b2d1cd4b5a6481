#!/bin/sh
# Regenerates the stills of docs/gallery.md: one PNG per shipped declarative scene, at the
# moment listed below, with the scene's own size and render settings (cairo renderer).
#   tools/gallery.sh [BUILD_DIR] [NAME...]     (default build; all scenes)
# Writes docs/gallery/<folder>_<scene>.png; scenes' own files go to a scratch folder.
# Imperative scripts (scenes/solids/*, scenes/examples/*) draw their own figures and are
# left out. About 10 minutes on 2 cores (the soil scenes are the slow ones).
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
B=${1:-build}
[ $# -gt 0 ] && shift
P="$ROOT/$B/app/porelab"
[ -x "$P" ] || P="$B/app/porelab"
[ -x "$P" ] || { echo "gallery.sh: no porelab in $B/app (build it first)" >&2; exit 1; }
OUT="$ROOT/docs/gallery"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$OUT"
# scene (under scenes/) and time of the still, s
LIST="
lab/buoyancy 3.0
lab/buoyancy_darcy 3.0
lab/floating_block 3.0
soil/liquefaction 4.0
soil/quicksand 4.6
soil/consolidation 1.45
soil/simple_shear 0.2
demo 0.9
fluid_quicksand 1.8
grains/shaking_table 3.0
grains/shear_box 1.0
heaps 6.235
disc_on_plate 2.5
five_discs 2.0
two_disc_impact 0.05
figures/buoyancy_case 150
figures/buoyancy_equal 150
figures/buoyancy_half 150
figures/buoyancy_heavy 53
figures/dam_flow 0.5
figures/polygon_packing 1.5
mimes/buoyancy 150
mimes/dam_flow 0.5
mimes/prop 20
navier_stokes/cavity 3.0
navier_stokes/cylinder_channel 2.0
navier_stokes/settling_disc 0.2
navier_stokes/settling_inertial 0.6
stokes/falling_disc 0.02
"
echo "$LIST" | while read -r name t; do
  [ -n "$name" ] || continue
  if [ $# -gt 0 ]; then
    want=0; for n in "$@"; do [ "$n" = "$name" ] && want=1; done
    [ $want = 1 ] || continue
  fi
  file=$(echo "$name" | tr / _).png
  if nice -n 10 "$P" still "$ROOT/scenes/$name.lua" --at "$t" -o "$OUT/$file" --out "$TMP/$file" -q \
       >"$TMP/log" 2>&1; then
    echo "gallery: $name at t = $t s -> docs/gallery/$file"
  else
    echo "gallery: $name FAILED:"; cat "$TMP/log"
  fi
done
