-- Rock cutting with a tool made of discrete elements (seed 002 §7.2, docs/rock.md): a block of
-- bonded rock discs (radius 1-1.5 mm) is cut by a square tool of bonded steel discs (radius
-- 0.5 mm) moving at a constant speed. Its top row is the holder (prescribed); the rest of the
-- tool is elastic. Friction heats the tool and the rock, heat flows through the contacts and
-- bonds, and the tool grains wear (Archard, hardness falling with temperature); a tool grain
-- whose worn volume reaches its size is removed. The tool makes several passes, each one a
-- little deeper; between passes the loose chips are cleared. Out: cutting.csv (force, tool
-- temperature, mass loss against time), cutting_force.png, tool_wear.png, tool_temperature.png;
-- frames with the cracks drawn.
--   porelab run scenes/rock/cutting.lua
-- The wear coefficient is accelerated (k = 200 instead of 1e-4..1e-6 for rock on carbide)
-- so that 40 ms of cutting wear away tool grains as hours of cutting would; the mass loss scales
-- linearly with k (Archard). The cutting force is the mean over each frame interval, from the
-- work the holder does: F = dW / (v dt).
local rock = require "porelab.rock"
local packing = require "porelab.packing"

local P = porelab.params {
  { name = "speed", unit = "m/s", value = 5, min = 0.1, max = 50, doc = "cutting speed" },
  { name = "depth", unit = "mm", value = 2.5, min = 0.5, max = 10, doc = "depth added by each pass" },
  { name = "passes", unit = "", value = 4, min = 1, max = 20, doc = "number of passes" },
  { name = "wear", unit = "", value = 200, min = 0, max = 10000, doc = "Archard coefficient of the tool (accelerated)" },
  { name = "length", unit = "mm", value = 90, min = 30, max = 300, doc = "length of the box the rock is compacted in" },
}
local w = porelab.world { gravity = { 0, 0 }, dt_safety = 0.2, local_damping = 0.7 } -- damped while the rock is made
local granite, steel = rock.lab_materials(w)
local tool_m = w:material { name = "tool", density = 7800, kn = 2e10, ks = 1e10, friction = 0.5 }
w:pair(granite, tool_m, { friction = 0.4 })
w:bond_law { a = tool_m, b = tool_m, law = "brittle", kn = 2e10, kt = 1e10, rn = 1e7, rt = 1e7 }

local L = P.length * 1e-3
local s = rock.specimen(w, { lo = { 0, 0 }, hi = { L, 0.5 * L }, material = granite, wall_material = steel,
                             fill_porosity = 0.6 })
print("cutting: rock " .. s.report)
local box = s.box
local xl = box.left:position()
local xr = box.right:position()
local _, yt = box.top:position()
box.top:set_state { position = { 0.5 * (xl + xr), yt + L } }
local surface = rock.surface(s.discs)
-- the left wall (length 0.5 L) is lowered below the deepest cut: the tool comes in from the left
local wall_top = surface - P.passes * P.depth * 1e-3 - 3e-3
box.left:set_state { position = { xl, wall_top - 0.25 * L } }
rock.rest(w, 1e-5, 5000)
-- cutting is dynamic: light damping from here on
w:set_flag("LOCAL_DAMPING", 0.1)

-- the tool: 6 mm x 8 mm of bonded discs, its lower edge `depth` below the surface
local tw, th, rt = 6e-3, 8e-3, 0.5e-3
local x_start = xl - tw - 2e-3
local function tool_at(x0, y0)
  return packing.lattice(w, { lo = { x0, y0 }, hi = { x0 + tw, y0 + th }, radius = rt, material = tool_m })
end
local depth = P.depth * 1e-3
local tool = tool_at(x_start, surface - depth)
local holder, top_y = {}, -math.huge
for _, d in ipairs(tool) do top_y = math.max(top_y, select(2, d:position())) end
for _, d in ipairs(tool) do
  if select(2, d:position()) > top_y - 0.5 * rt then holder[#holder + 1] = d end
end
w:bond_touching(1e-6)
for _, d in ipairs(holder) do d:set_velocity(P.speed, 0) end
local holder_x0 = holder[1]:position()

w:thermal { material = granite, heat_capacity = 800, conductivity = 3 }
w:thermal { material = tool_m, heat_capacity = 460, conductivity = 50, wear = P.wear, hardness = 2e9,
            softening = 1e-3, h_min = 0.2 }
w:thermal { material = steel, heat_capacity = 460, conductivity = 0 }
w:heat { fraction = 1, initial = 293.15 }
w:wear { remove = true }
print(string.format("cutting: rock %.0f x %.0f mm, tool %d discs (%d in the holder), depth %.1f mm per pass, speed %g m/s, dt %.3g s",
                    (xr - xl) * 1e3, surface * 1e3, #tool, #holder, P.depth, P.speed, w:dt()))

local x_end = xr - 20e-3              -- the tool's front stops short of the far wall
local pass_time = (x_end - (x_start + tw)) / P.speed
local t0 = w:time()
local tool_mass = 0
for _, d in ipairs(tool) do tool_mass = tool_mass + d:mass() end

local function tool_state()
  local T, Tmax, n, loss = 0, 0, 0, 0
  for _, d in ipairs(tool) do
    local gone = w:removed(d)
    if gone then
      loss = loss + d:mass()
    else
      local Ti = w:temperature(d)
      T, Tmax, n = T + Ti, math.max(Tmax, Ti), n + 1
      loss = loss + 7800 * math.min(w:body_wear(d), d:area())
    end
  end
  return T / math.max(n, 1), loss, Tmax
end
-- mean cutting force since the last call: the work the holder did over the distance it moved
local w_last, t_last = nil, nil
local function cutting_force(world)
  local W, t = world:energy().external, world:time()
  local f = (w_last and t > t_last) and (W - w_last) / (P.speed * (t - t_last)) or 0
  w_last, t_last = W, t
  return f
end
local csv = porelab.csv("cutting.csv", { "t", "pass", "cutting_force", "tool_temperature", "tool_temperature_max", "tool_mass_loss", "tool_grains_removed" },
                        { "s", "", "N/m", "K", "K", "kg/m", "" })
local ts, fc, temp, tmax, loss, removed = {}, {}, {}, {}, {}, {}
local pass, cut_time, last_t = 1, 0, t0
local function removed_tool()
  local n = 0
  for _, d in ipairs(tool) do if w:removed(d) then n = n + 1 end end
  return n
end

-- next pass: clear the chips above the cut just made, bring the tool back, one depth lower
local function next_pass()
  local level = surface - pass * depth
  for _, d in ipairs(s.discs) do
    if not w:removed(d) then
      local _, y = d:position()
      if y > level then w:remove(d) end
    end
  end
  pass = pass + 1
  local ox = select(1, holder[1]:position()) - holder_x0
  -- every tool disc moves back by the holder's travel, and one depth down
  for _, d in ipairs(tool) do
    if not w:removed(d) then
      local x, y = d:position()
      d:set_state { position = { x - ox, y - depth } }
    end
  end
end

local total = P.passes * pass_time
return {
  world = w,
  run = { t_end = t0 + total + 1e-9, every = math.max(1, math.floor(pass_time / w:dt() / 60)) },
  render = {
    size = { 1000, 520 },
    camera = { x_start - 2e-3, -2e-3, xr + 2e-3, surface + 14e-3 },
    time_offset = -t0,
    colors = { granite = "#c9c2b6", steel = "#3a3a3a", tool = "#6b7a8f" },
    layers = { "bodies", "bonds", "time", "title" },
    title = "Rock cutting with a tool of discrete elements",
  },
  on_frame = function(world)
    local T, m, Tm = tool_state()
    local f = cutting_force(world)
    local k = #ts + 1
    cut_time = cut_time + (world:time() - last_t)
    last_t = world:time()
    ts[k], fc[k], temp[k], tmax[k], loss[k], removed[k] = cut_time, f, T, Tm, m, removed_tool()
    csv:row(cut_time, pass, f, T, Tm, m, removed[k])
    if world:time() - t0 >= pass * pass_time - 1e-12 and pass < P.passes then
      next_pass()
      cutting_force(world) -- the chips taken away do no work: start the next interval here
    end
  end,
  on_finish = function(world)
    local T, m, Tm = tool_state()
    local fm = 0
    for k = 1, #fc do fm = fm + fc[k] / #fc end
    print(string.format("cutting: %d passes, %.3g ms of cutting; mean cutting force %.4g N/m, tool at %.2f K (hottest grain %.2f K), tool mass loss %.4g g/m (%.2f %%), %d tool grains removed",
                        pass, 1e3 * cut_time, fm, T, Tm, 1e3 * m, 100 * m / tool_mass, removed_tool()))
    local x, y1, y2, y3, y4 = {}, {}, {}, {}, {}
    for k = 1, #ts do x[k], y1[k], y2[k], y3[k], y4[k] = 1e3 * ts[k], fc[k] / 1e3, temp[k] - 273.15, 1e3 * loss[k], tmax[k] - 273.15 end
    porelab.chart { file = "cutting_force.png", title = "Cutting force", xlabel = "cutting time (ms)",
                    ylabel = "cutting force (kN per m of thickness)", legend = "none",
                    series = { { name = "cutting force", x = x, y = y1 } } }
    porelab.chart { file = "tool_wear.png", title = "Tool mass loss", xlabel = "cutting time (ms)",
                    ylabel = "tool mass loss (g per m of thickness)", legend = "none",
                    series = { { name = "tool mass loss", x = x, y = y3 } } }
    porelab.chart { file = "tool_temperature.png", title = "Tool temperature", xlabel = "cutting time (ms)",
                    ylabel = "tool temperature (°C)", legend = "top left",
                    series = { { name = "hottest tool grain", x = x, y = y4 },
                               { name = "mean over the tool", x = x, y = y2, style = "dashed" } } }
  end,
  results = function(world)
    local T, m = tool_state()
    return { tool_mass_loss = { value = m, unit = "kg/m" }, tool_temperature = { value = T, unit = "K" },
             tool_grains_removed = removed_tool() }
  end,
}
