-- Description: The water rises when a block goes in: the level follows the displaced volume.
-- Classroom lab: the water rises when a block goes in (docs/hydrostatic.md). A narrow tank of
-- still water; a wooden block is dropped in. The water's amount is fixed (moving level): the
-- block pushes water aside, so the level rises by the block's submerged area divided by the
-- tank's width. Floating, the block displaces its own weight of water: the rise is
-- m / (rho_f W) = (rho_b / rho_f) A / W, whatever its shape.
-- Open it live:  porelab view scenes/lab/floating_block.lua
-- Parameters (tab selects, up/down changes): the block's density (above 1000 kg/m3 it sinks and
-- the rise is its whole area / W) and the water's density.
local W, H = 0.12, 0.15                -- tank width and initial water depth, m
local L, B = 0.07, 0.05                -- block width and height, m
local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 6 }
local wall = w:material { name = "tank", density = 2500, kn = 2e5, friction = 0.4, restitution = 0.2 }
local wood = w:material { name = "wood", density = 600, kn = 2e5, friction = 0.4, restitution = 0.2 }

w:wall { from = { -0.01, 0 }, to = { W + 0.01, 0 }, material = wall }
w:wall { from = { 0, 0 }, to = { 0, 0.30 }, material = wall }
w:wall { from = { W, 0 }, to = { W, 0.30 }, material = wall }

-- the water first (its area is fixed now: the block starts above it)
w:water { x_min = 0, x_max = W, bottom = 0, level = H, density = 1000, moving_level = true }
local block = w:rectangle { center = { W / 2, 0.22 }, width = L, height = B, material = wood }

local rho_b, rho_f = 600, 1000
local params = {
  { name = "block density", unit = "kg/m³", value = rho_b, min = 100, max = 3000, step = 100,
    set = function(world, v) rho_b = v; block:set_density(v) end },
  { name = "water density", unit = "kg/m³", value = rho_f, min = 500, max = 2000, step = 100,
    set = function(world, v) rho_f = v; world:water_set { density = v } end },
}

local function overlay(world)
  local level = world:water_level()
  -- expected rise once at rest: floating, the displaced area is (rho_b / rho_f) A; sunk, A
  local expect = math.min(rho_b / rho_f, 1) * L * B / W
  return {
    { polygon = { { 0, 0 }, { W, 0 }, { W, level }, { 0, level } }, fill = { 0.35, 0.6, 0.95, 0.45 },
      color = { 0.12, 0.3, 0.62, 1 }, width = 1 },
    { line = { { -0.01, H }, { 0, H } }, color = "#d62728", width = 2 },
    -- left of the tank, clear of its wall: the rise so far and the rise expected at rest
    { text = string.format("rise %+.2f mm", 1000 * (level - H)), at = { 12, 56 }, space = "pixel", size = 15 },
    { text = string.format("at rest %+.2f mm", 1000 * expect), at = { 12, 78 }, space = "pixel", size = 15 },
  }
end

return {
  world = w,
  params = params,
  run = { t_end = 4.0, fps = 30 },
  render = { size = { 600, 700 }, camera = { -0.03, -0.02, W + 0.03, 0.30 },
             layers = "bodies,overlay,title,time,scalebar", overlay = overlay,
             colors = { wood = "#b5834a", tank = "#555555" },
             title = "The water rises: a block in a narrow tank" },
}
