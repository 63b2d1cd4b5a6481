-- Seed 000 Fig. 4-8: a particle denser than the fluid (1.5 times) sinks to the bottom. It sinks
-- at about 3.3 per second and lands on the floor at t = 53 s (lowest point 0.4 above it),
-- where the figure is taken. Afterwards it sinks on into the soft floor of the listing
-- (E = 200 for the area-based polygon contact, while the fluid's lift falls as the particle
-- leaves the mesh) until the overlap guard stops the run at t = 55.6 s.
--   porelab still scenes/figures/buoyancy_heavy.lua --at 53 -o fig.png   (tools/figures.sh)
return require("buoyancy_case")(1.5, "sinks to the bottom")
