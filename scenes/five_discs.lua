-- Tan (1990) §2.2.5.2, Table 2.2: five frictionless discs (R = 1 m,
-- m = 7539.823 kg) settle under g = 10 m/s^2 between a floor (wall 1) and two side walls
-- (walls 2 and 3). k_N = 1e7 N/m, c_N = 1e5 N s/m, global C = 4.5e5 N s/m, 5 s.
-- Written with the MIMES flags of Klosek (1997) (GRAVITY_Y, GLOBAL_DAMPING, TIMESTEPS, PRINT_INT).
-- Geometry reconstructed from the table: discs 1, 2 on the floor against the side walls,
-- disc 3 on top of them, discs 4, 5 against the walls on top of disc 3; every line of
-- centres makes 41.4 degrees with the horizontal (dx = 1.5 m, dy = sqrt(1.75) m).
local w = porelab.world {
  dt = 1e-3,
  flags = { GRAVITY_Y = -10, GLOBAL_DAMPING = 4.5e5, TIMESTEPS = 5000, PRINT_INT = 100 },
}
local rock = w:material { name = "rock", density = 2400, kn = 1e7, ks = 0, friction = 0,
                          cn = 1e5, cs = 0 }

local dy = math.sqrt(1.75)
w:wall { from = { -2.5, 0 }, to = { 2.5, 0 }, material = rock }      -- wall 1 (floor)
w:wall { from = { -2.5, 6 }, to = { -2.5, 0 }, material = rock }     -- wall 2 (left)
w:wall { from = { 2.5, 0 }, to = { 2.5, 6 }, material = rock }       -- wall 3 (right)
local discs = {
  w:disc { center = { -1.5, 1 }, radius = 1, material = rock },            -- disc 1
  w:disc { center = { 1.5, 1 }, radius = 1, material = rock },             -- disc 2
  w:disc { center = { 0, 1 + dy }, radius = 1, material = rock },          -- disc 3
  w:disc { center = { -1.5, 1 + 2 * dy }, radius = 1, material = rock },   -- disc 4
  w:disc { center = { 1.5, 1 + 2 * dy }, radius = 1, material = rock },    -- disc 5
}

-- Theoretical forces of Table 2.2 (rigid discs in the initial geometry), N; keys name the
-- lower-numbered disc first, walls last.
local theory = { ["1-w1"] = 188495.6, ["1-w2"] = 128247.7, ["2-w1"] = 188495.6,
                 ["2-w3"] = 128247.7, ["1-3"] = 170996.9, ["2-3"] = 170996.9,
                 ["3-4"] = 113997.9, ["3-5"] = 113997.9, ["4-w2"] = 85498.4,
                 ["5-w3"] = 85498.4 }

local function name(i)
  for k, d in ipairs(discs) do if d:index() == i then return tostring(k), k end end
  return "w" .. tostring(i), 100 + i -- walls are bodies 1..3
end

local function key(c)
  local a, ka = name(c.a)
  local b, kb = name(c.b)
  if ka > kb then a, b = b, a end
  return a .. "-" .. b
end

-- The picture is Tan's Fig. 2.13(a): force chains between the centres (width
-- proportional to the normal force, 200 kN at full width) and, at each contact, the computed
-- normal force beside the rigid-disc value of Table 2.2 in parentheses, kN; a wall's contact
-- force is labelled outside that wall, clear of the wall line and the discs
--   porelab still scenes/five_discs.lua --at 5 -o five.png   (tools/figures.sh)
return {
  world = w,
  render = {
    size = { 860, 780 },
    camera = { -4.3, -1.1, 4.3, 6.2 },
    force_scale = 2e5,
    force_max_width = 16,
    force_threshold = 0,
    layers = "bodies,forces,overlay,title,time",
    title = "Five settled discs: contact forces (kN)",
    colors = { rock = "#d9cbb0" },
    overlay = function(world)
      local items = {
        { text = "wall 1", at = { 0, -0.75 }, anchor = "center", size = 15 },
        { text = "wall 2", at = { -2.65, 5.6 }, anchor = "right", size = 15 },
        { text = "wall 3", at = { 2.65, 5.6 }, anchor = "left", size = 15 },
        { text = "computed (rigid discs, Tan 1990 Table 2.2)", at = { 0, 5.75 },
          anchor = "center", size = 15 },
      }
      for k, d in ipairs(discs) do
        local x, y = d:position()
        items[#items + 1] = { text = tostring(k), at = { x, y + 0.45 }, anchor = "center",
                              size = 22 }
      end
      for _, c in ipairs(world:contacts()) do
        local ref = theory[key(c)]
        local label = string.format("%.1f", c.fn / 1000)
        if ref then label = label .. string.format(" (%.1f)", ref / 1000) end
        local x, y = c.point[1] or c.point.x, c.point[2] or c.point.y
        local k = key(c)
        local anchor = "center"
        if k:find("w1", 1, true) then y = y - 0.3                        -- below the floor
        elseif k:find("w2", 1, true) then x, anchor = x - 0.12, "right"  -- left of wall 2
        elseif k:find("w3", 1, true) then x, anchor = x + 0.12, "left"   -- right of wall 3
        end
        items[#items + 1] = { text = label, at = { x, y }, anchor = anchor, size = 15,
                              color = "#7a1010" }
      end
      return items
    end,
  },
  on_finish = function(world)
    for _, c in ipairs(world:contacts()) do
      local k = key(c)
      local ref = theory[k]
      print(string.format("disc %-5s %10.1f N   theory %10s N", k, c.fn,
                          ref and string.format("%.1f", ref) or "-"))
    end
  end,
}
