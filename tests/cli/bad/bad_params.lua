-- bad input: a scene parameter whose bounds are the wrong way round (min > max)
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
local d = w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return {
  world = w,
  params = {
    { name = "density", value = 2650, min = 1000, max = 5000, set = function(world, v) d:set_density(v) end },
    { name = "friction", value = 0.5, min = 0.9, max = 0.1, set = function(world, v) end },
  },
}
