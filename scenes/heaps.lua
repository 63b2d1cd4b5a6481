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

-- A random convex polygon inscribed in an ellipse (corners at jittered parametric angles,
-- so they stay ordered and the outline convex), as porelab's pl_shape_random_polygon.
local rng = random.new(2020)
local function random_polygon(cx, cy)
  local n = rng:integer(5, 9)
  local a = rng:uniform(0.005, 0.0075)
  local b = a * rng:uniform(0.6, 1.0)
  local phase = rng:uniform(0, 2 * math.pi)
  local rot = rng:uniform(0, 2 * math.pi)
  local c, s = math.cos(rot), math.sin(rot)
  local v = {}
  for k = 0, n - 1 do
    local t = phase + 2 * math.pi * (k + 0.5 * (rng:uniform() - 0.5)) / n
    local x, y = a * math.cos(t), b * math.sin(t)
    v[#v + 1] = { cx + c * x - s * y, cy + s * x + c * y }
  end
  return v
end

-- Area of an outline (shoelace), for the disc of the same area.
local function area(v)
  local s = 0
  for i = 1, #v do
    local p, q = v[i], v[i % #v + 1]
    s = s + p[1] * q[2] - q[1] * p[2]
  end
  return 0.5 * s
end

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
    local v = random_polygon(xp + dx, yp)
    w:polygon { vertices = v, material = grain }
    w:disc { center = { xd + dx, yd }, radius = math.sqrt(area(v) / math.pi), material = disc }
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
