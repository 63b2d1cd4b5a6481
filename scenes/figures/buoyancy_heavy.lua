-- Seed 000 Fig. 4-8: a particle denser than the fluid (1.5 times) sinks to the bottom. It sinks
-- at about 3.3 per second and lands on the floor at t = 53 s (lowest point 0.4 above it),
-- where the figure is taken, and rests there to the end (t = 200 s), its lowest point 1.07
-- below the floor's top (the listing's k_N = 400000 with the area-based polygon law).
--   porelab still scenes/figures/buoyancy_heavy.lua --at 53 -o fig.png   (tools/figures.sh)
return require("buoyancy_case")(1.5, "sinks to the bottom")
