-- Description: What floats? The same lab with the water as a Darcy pressure field.
-- Classroom lab: what floats? -- the Darcy-model version of scenes/lab/buoyancy.lua (which uses
-- the cheaper hydrostatic water; docs/hydrostatic.md compares them: the same drafts). A tank of still water with
-- three blocks and a handful of pebbles. The water pressure rises with depth (hydrostatic,
-- layer "pressure"); the pressure around each body's outline pushes it up with the weight of
-- the water it displaces (Archimedes). A body floats when its density is below the water's.
-- Open it live:  porelab view scenes/lab/buoyancy_darcy.lua
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

w:fluid_quad { corners = { { 0, 0 }, { W, 0 }, { W, H }, { 0, H } }, ndivx = 16, ndivy = 12 }
w:fluid_bc { from = { 0, H }, to = { W, H }, head = 0 }
w:set_flag("FLUIDS_ON", 1)
w:set_flag("FLUID_DENSITY", 1000)
w:set_flag("FLUID_STORAGE", 0)
w:set_flag("FLUID_SOLVE_TIMESTEPS", 20)

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
    set = function(world, v) world:set_flag("FLUID_DENSITY", v) end },
}

return {
  world = w,
  params = params,
  run = { t_end = 4.0, fps = 30 },
  render = { size = { 800, 600 }, camera = { -0.03, -0.02, W + 0.03, 0.44 },
             layers = "bodies,pressure,isolines,colorbar,scalebar,title,time",
             colors = { wood = "#b5834a", ice = "#d8eef7", brick = "#a8442c", pebble = "#8c8c8c", tank = "#555555" },
             title = "What floats? wood, ice, brick in water",
             -- the window's live chart (porelab view: "charts"): how high each block sits
             live = { { title = "height above the tank floor (cm)", range = { 0, 42 },
                        series = { { name = "wood", color = "#d9a25f", value = function() return 100 * select(2, blocks[1]:position()) end },
                                   { name = "ice", color = "#8fd3f0", value = function() return 100 * select(2, blocks[2]:position()) end },
                                   { name = "brick", color = "#e0603f", value = function() return 100 * select(2, blocks[3]:position()) end } } } } },
}
