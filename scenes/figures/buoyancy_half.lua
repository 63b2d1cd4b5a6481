-- Seed 000 Fig. 4-6: a particle of half the fluid's density floats half submerged.
--   porelab still scenes/figures/buoyancy_half.lua --at 150 -o fig.png   (tools/figures.sh)
return require("buoyancy_case")(0.5, "floats, half submerged")
