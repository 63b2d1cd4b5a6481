-- Seed 000 Fig. 4-7: a particle as dense as the fluid comes to rest just under the surface.
--   porelab still scenes/figures/buoyancy_equal.lua --at 150 -o fig.png   (tools/figures.sh)
return require("buoyancy_case")(1.0, "rests just under the surface")
