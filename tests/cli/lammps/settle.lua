-- A small dry packing for the LAMMPS export test (tests/cli/lammps/lammps_settle.sh): 150 discs
-- of two sizes rained into a box of three walls settle under gravity. The results are the
-- settled packing's contact diagnostics, defined as `porelab import-lammps` defines them:
-- coordination (pl_world_coordination_number), mean normal contact force and mean overlap
-- over every touching contact (disc pairs and walls).
local packing = require "porelab.packing"

local w = porelab.world { gravity = { 0, -9.81 }, dt_safety = 0.2 }
local sand = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5, restitution = 0.4 }
local steel = w:material { name = "steel", density = 7800, kn = 1e6, friction = 0.5, restitution = 0.4 }
packing.box(w, { lo = { 0, 0 }, hi = { 0.12, 0.25 }, material = steel })
packing.rain(w, { lo = { 0.006, 0.006 }, hi = { 0.114, 0.2 }, radii = { 0.004, 0.005 },
                  count = 150, material = sand, seed = 7 })

return {
  world = w,
  run = { t_end = 1.5, fps = 10 },
  render = { layers = { "bodies", "forces", "time" } },
  results = function(world)
    local n, fsum, osum = 0, 0, 0
    for _, c in ipairs(world:contacts()) do
      n = n + 1
      fsum = fsum + c.fn
      osum = osum + c.overlap
    end
    return {
      coordination = world:coordination(),
      contacts = n,
      mean_fn = { value = n > 0 and fsum / n or 0, unit = "N" },
      mean_overlap = { value = n > 0 and osum / n or 0, unit = "m" },
    }
  end,
}
