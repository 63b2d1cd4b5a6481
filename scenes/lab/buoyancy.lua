-- Description: What floats? Wood, ice and brick in still water, with their weight and buoyancy.
-- Classroom lab: what floats? (docs/classroom.md, lesson 1). A tank of still water with
-- three blocks and a handful of pebbles. The water pressure rises with depth (hydrostatic:
-- p = rho g depth, layer "pressure" with its isobars); the pressure around each
-- body's outline pushes it up with the weight of the water it displaces (Archimedes). A body
-- floats when its density is below the water's.
-- The water is the hydrostatic model (docs/hydrostatic.md): the exact pressure integral over
-- each outline, no mesh. scenes/lab/buoyancy_darcy.lua is the same lab with the Darcy model.
-- Open it live:  porelab view scenes/lab/buoyancy.lua
-- Parameters (tab selects, up/down changes, while it runs): the density of each block and
-- of the water.
local W, H = 0.40, 0.30                -- tank width and water depth, m
local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 4 }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
local wood = w:material { name = "wood", density = 600, kn = 2e5, friction = 0.4, restitution = 0.2 }
local ice = w:material { name = "ice", density = 920, kn = 2e5, friction = 0.4, restitution = 0.2 }
local brick = w:material { name = "brick", density = 1900, kn = 2e5, friction = 0.4, restitution = 0.2 }
local stone = w:material { name = "pebble", density = 2650, kn = 2e5, friction = 0.4, restitution = 0.2 }

w:wall { from = { -0.02, 0 }, to = { W + 0.02, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.42 }, material = wall }
w:wall { from = { W, 0 }, to = { W, 0.42 }, material = wall }

local blocks = {
  w:rectangle { center = { 0.08, 0.36 }, width = 0.07, height = 0.04, material = wood },
  w:rectangle { center = { 0.20, 0.36 }, width = 0.06, height = 0.05, material = ice },
  w:rectangle { center = { 0.32, 0.36 }, width = 0.06, height = 0.04, material = brick },
}
for i = 0, 7 do
  w:disc { center = { 0.03 + 0.045 * i, 0.02 + 0.01 * (i % 2) }, radius = 0.012, material = stone }
end

-- the water's amount is fixed: a block that goes in pushes the level up (moving level)
w:water { x_min = 0, x_max = W, bottom = 0, level = H, density = 1000, moving_level = true }

local function density_param(name, i, rho)
  return { name = name, unit = "kg/m³", value = rho, min = 100, max = 3000, step = 100,
           set = function(world, v) blocks[i]:set_density(v) end }
end

-- Parameters the window lets you change while it runs (porelab view: tab, up/down).
local params = {
  density_param("wood block", 1, 600),
  density_param("ice block", 2, 920),
  density_param("brick block", 3, 1900),
  { name = "water density", unit = "kg/m³", value = 1000, min = 500, max = 2000, step = 100,
    set = function(world, v) world:water_set { density = v } end },
}

-- The picture: each block with its name, density and mass, its weight (down, from its centre)
-- and the buoyancy (up, from the centre of its submerged part: rho_f g times the submerged
-- area, per metre of depth), both to one scale; the water surface with its rise.
local rho_f, G = 1000, 9.81
local names = { "wood", "ice", "brick" }
local N_PER_M = 0.0015 -- m of arrow per N/m of force

-- part of a polygon below the level y = lv: its area and centroid
local function submerged(v, lv)
  local out = {}
  for k = 1, #v do
    local a, b = v[k], v[k % #v + 1]
    if a[2] <= lv then out[#out + 1] = a end
    if (a[2] - lv) * (b[2] - lv) < 0 then
      local t = (lv - a[2]) / (b[2] - a[2])
      out[#out + 1] = { a[1] + t * (b[1] - a[1]), lv }
    end
  end
  local A, cx, cy = 0, 0, 0
  for k = 1, #out do
    local a, b = out[k], out[k % #out + 1]
    local c = a[1] * b[2] - b[1] * a[2]
    A, cx, cy = A + c, cx + (a[1] + b[1]) * c, cy + (a[2] + b[2]) * c
  end
  if math.abs(A) < 1e-12 then return 0, nil end
  return A / 2, { cx / (3 * A), cy / (3 * A) }
end

local function overlay(world)
  local lv = world:water_level()
  local items = {
    { line = { { 0, lv }, { W, lv } }, color = "#1f4e9c", width = 2 },
    { text = string.format("water surface %+.1f mm", math.abs(lv - H) < 5e-5 and 0 or 1000 * (lv - H)), at = { W - 0.005, lv + 0.006 },
      anchor = "right", size = 14, color = "#1f4e9c" },
  }
  for i, b in ipairs(blocks) do
    local x, y = b:position()
    local m = b:mass()
    local weight = m * G
    local A, c = submerged(b:vertices(), lv)
    local buoy = rho_f * G * A
    items[#items + 1] = { arrow = { { x - 0.004, y }, { x - 0.004, y - N_PER_M * weight } }, color = "#b00000", width = 3 }
    if c then
      items[#items + 1] = { arrow = { { c[1] + 0.004, c[2] }, { c[1] + 0.004, c[2] + N_PER_M * buoy } },
                            color = "#1f4e9c", width = 3 }
    end
    -- name, density and mass in a row above the tank, over each block
    items[#items + 1] = { text = string.format("%s %.0f kg/m\u{00B3}", names[i], m / b:area()),
                          at = { x, 0.405 }, anchor = "center", size = 14 }
    items[#items + 1] = { text = string.format("%.2f kg per m", m), at = { x, 0.392 },
                          anchor = "center", size = 12 }
  end
  -- key, in the air above the water
  items[#items + 1] = { arrow = { { 0.262, 0.368 }, { 0.285, 0.368 } }, color = "#b00000", width = 3 }
  items[#items + 1] = { text = "weight", at = { 0.29, 0.368 }, anchor = "left", size = 14 }
  items[#items + 1] = { arrow = { { 0.262, 0.350 }, { 0.285, 0.350 } }, color = "#1f4e9c", width = 3 }
  items[#items + 1] = { text = "buoyancy", at = { 0.29, 0.350 }, anchor = "left", size = 14 }
  return items
end

return {
  world = w,
  params = params,
  run = { t_end = 4.0, fps = 30 },
  render = { size = { 800, 640 }, camera = { -0.03, -0.02, W + 0.03, 0.46 },
             layers = "bodies,pressure,isolines,colorbar,scalebar,title,time,overlay",
             fluid_range = { 0, 3200 }, isolines = 6,
             colors = { wood = "#b5834a", ice = "#d8eef7", brick = "#a8442c", pebble = "#8c8c8c", tank = "#555555" },
             overlay = overlay,
             title = "What floats? Wood, ice and brick in water",
             -- the window's live chart (porelab view: "charts"): how high each block sits
             live = { { title = "height above the tank floor (cm)", range = { 0, 42 },
                        series = { { name = "wood", color = "#d9a25f", value = function() return 100 * select(2, blocks[1]:position()) end },
                                   { name = "ice", color = "#8fd3f0", value = function() return 100 * select(2, blocks[2]:position()) end },
                                   { name = "brick", color = "#e0603f", value = function() return 100 * select(2, blocks[3]:position()) end } } } } },
}
