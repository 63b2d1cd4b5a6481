-- A declarative scene that returns its adjustable parameters in the result table (the live
-- window lists them; porelab run checks them and otherwise ignores them).
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:wall { from = { -1, 0 }, to = { 1, 0 }, material = m }
local grain = w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
return {
  world = w,
  run = { t_end = 0.05, fps = 20 },
  params = {
    { name = "grain density", unit = "kg/m3", value = 2650, min = 1000, max = 5000, step = 250,
      set = function(world, v) grain:set_density(v) end },
    { name = "gravity", unit = "m/s2", value = 9.81, min = 0, max = 20,
      set = function(world, v) world:set_flag("GRAVITY_Y", -v) end },
  },
}
