-- Polygon heap next to a disc heap (seed 004 §2.1, Fig. 1). The same 150 grains are poured
-- twice from a point source, three every 0.06 s, 2.5 cm above the top of the heap: on the
-- left as random convex polygons inscribed in ellipses (5-9 corners, half axes 5-7.5 mm,
-- aspect 0.6-1), on the right as discs of the same areas. Same density, stiffness,
-- restitution and friction (mu = 0.5). The polygons build a heap of about 27 degrees; the
-- discs roll apart into a low mound of about 3-10 degrees (tests/polygon/test_polygon_heap.c
-- measures both on a plain floor). The polygons use the area-based contact law of seed 004 §3
-- (docs/contact-laws-polygons.md).
--   porelab run scenes/heaps.lua        (frames in out/heaps/; grains are added in on_frame,
--   one batch per frame, so keep the scene's frame rate)
local random = require "porelab.random"

local w = porelab.world { gravity = { 0, -9.81 } }

local grain = w:material { name = "grain", density = 2650, kn = 1e5, friction = 0.5,
                           restitution = 0.3 }
local disc = w:material { name = "disc", density = 2650, kn = 1e5, friction = 0.5,
                          restitution = 0.3 }
local steel = w:material { name = "steel", density = 7800, kn = 1e5, friction = 0.5,
                           restitution = 0.3 }

-- Two trays side by side, each 0.8 m wide with 3 cm rims (wide enough that the discs are
-- not held up by the rims).
local function tray(x0, x1)
  w:wall { from = { x0, 0 }, to = { x1, 0 }, material = steel }
  w:wall { from = { x0, 0.03 }, to = { x0, 0 }, material = steel }
  w:wall { from = { x1, 0 }, to = { x1, 0.03 }, material = steel }
end
tray(-0.82, -0.02)
tray(0.02, 0.82)
local first_grain = w:body_count() + 1

local xp, xd = -0.42, 0.42   -- pour points, m
local count, per_batch, period = 150, 3, 0.06

local rng = random.new(2020)
local seed = 0

-- Height of the highest slow grain centre within 3 cm of x (the heap's top; grains still
-- falling do not count, but a new batch starts 1.6 cm clear of them).
local function top(x)
  local h, high = 0, 0
  for i = first_grain, w:body_count() do
    local b = w:body(i)
    local bx, by = b:position()
    local vx, vy = b:velocity()
    if math.abs(bx - x) < 0.03 then
      if by > h and vx * vx + vy * vy < 0.01 then h = by end
      if by > high then high = by end
    end
  end
  return math.max(h, high - 0.025 + 0.016)
end

local poured = 0
local function pour()
  if poured >= count then return end
  local yp, yd = top(xp) + 0.025, top(xd) + 0.025
  for j = 0, per_batch - 1 do
    if poured >= count then break end
    local dx = -0.015 + 0.015 * j + rng:uniform(-0.002, 0.002)
    -- seed 004 §2.1 grains: 5-9 corners on ellipses with half axes 5-7.5 mm, aspect 0.6-1
    seed = seed + 1
    local p = w:random_polygon { center = { xp + dx, yp }, seed = seed, corners = { 5, 9 },
                                 axis = { 0.005, 0.0075 }, aspect = { 0.6, 1.0 }, material = grain }
    w:disc { center = { xd + dx, yd }, radius = math.sqrt(p:area() / math.pi), material = disc }
    poured = poured + 1
  end
end

local fps = 1 / period   -- one frame per batch
pour()

return {
  world = w,
  run = { t_end = 8.0, fps = fps },
  render = {
    size = { 1600, 200 },
    camera = { -0.84, -0.02, 0.84, 0.19 },
    colors = { grain = "#d9a75f", disc = "#9dbbdc", steel = "#3a3a3a" },
    layers = { "bodies", "time", "title" },
    title = "Polygons (left) and discs (right), same friction: angle of repose",
  },
  on_frame = function(world, frame)
    pour()
  end,
}
