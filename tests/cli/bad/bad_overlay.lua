-- bad input: an overlay item with a negative circle radius, drawn from a function
local w = porelab.world {}
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
return {
  world = w,
  render = {
    overlay = function(world)
      return { { text = "ok", at = { 0, 0 } }, { circle = { 0, 0 }, radius = -1 } }
    end,
  },
}
