-- Lua-level test of the hydrostatic water binding (lua/wrap_hydrostatic.c); an imperative
-- script: any failed check raises, and porelab exits non-zero. Run by ctest as
-- fluid_lua_hydrostatic (tests/fluid/tests.cmake).
local function check(cond, fmt, ...)
  if not cond then error(string.format(fmt, ...), 2) end
end
local function fails(pattern, f, ...)
  local ok, err = pcall(f, ...)
  check(not ok, "expected an error matching '%s'", pattern)
  check(tostring(err):find(pattern), "error '%s' does not match '%s'", tostring(err), pattern)
  return err
end

local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 16 }
-- errors: unknown field (listing the valid ones), ranges from the table, file:line
local err = fails("unknown field 'levle'", w.water, w, { levle = 0.3 })
check(err:find("valid: .*level") and err:find("moving_level"), "the valid names are listed: %s", err)
check(err:find("lua_hydrostatic_api.lua:%d+:"), "file:line in '%s'", err)
fails("density must be a number in %[1e%-30, 1e%+30%] kg/m%^3 %(got %-1%)", w.water, w, { density = -1 })
fails("drag must be a number in %[0,", w.water, w, { drag = -2 })
fails("moving_level must be an integer in %[0, 1%]", w.water, w, { moving_level = 3 })
fails("moving_level must be a number or a boolean %(got string%)", w.water, w, { moving_level = "yes" })
fails("x_max %(0 m%) must be greater than x_min %(0 m%)", w.water, w, { x_min = 0, x_max = 0 })
fails("level %-0.1 m is below the bottom", w.water, w, { level = -0.1 })
fails("level must be a number %(got string%)", w.water, w, { level = "high" })
fails("no water", w.water_level, w)
fails("no water yet", w.water_set, w, { density = 1200 })

-- a wood block in a 0.2 m tank; the water after the block exists, so its area excludes the
-- block's submerged part
local m = w:material { name = "wood", density = 500, kn = 2e5 }
local b = w:rectangle { center = { 0.1, 0.3 }, width = 0.1, height = 0.04, material = m }
w:water { x_min = 0, x_max = 0.2, bottom = 0, level = 0.3, density = 1000, moving_level = true }
fails("already has hydrostatic water", w.water, w, {})
check(math.abs(w:water_level() - 0.3) < 1e-15, "level %g", w:water_level())
check(math.abs(w:water_pressure(0.05, 0.1) - 1000 * 9.81 * 0.2) < 1e-9, "pressure %g", w:water_pressure(0.05, 0.1))
check(w:water_pressure { 0.05, 0.35 } == 0, "no pressure above the surface")
check(w:water_pressure(0.3, 0.1) == 0, "no pressure outside the tank")
w:step(10000)
local x, y = b:position()
local level = w:water_level()
-- half density: half of the 0.04 m height under water, at rest
local draft = level - (y - 0.02)
check(math.abs(draft - 0.02) < 2e-5, "draft %.6f (0.02)", draft)
-- the block started half submerged at the given level, so that level is kept
check(math.abs(level - 0.3) < 1e-6, "level %.9f", level)
-- a denser water lifts it: draft rho_b / rho_f h
w:water_set { density = 2000 }
w:step(10000)
x, y = b:position()
draft = w:water_level() - (y - 0.02)
check(math.abs(draft - 0.01) < 1e-5, "draft in denser water %.6f (0.01)", draft)
fails("water_set: .*drag must be", w.water_set, w, { drag = -1 })
local d = w:water_def()
check(d.density == 2000 and d.moving_level == 1 and d.x_max == 0.2 and d.level == w:water_level(),
      "water_def: density %s, moving_level %s, level %s", tostring(d.density), tostring(d.moving_level), tostring(d.level))
print(string.format("lua hydrostatic: ok (draft %.6f m, level %.6f m)", draft, w:water_level()))
