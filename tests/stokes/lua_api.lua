-- The Lua face of the boundary-element Stokes model (lua/wrap_stokes.c): every bad argument of
-- w:stokes{...} gives one message naming this file and line, the argument and its valid
-- range; the queries return what docs/stokes.md says. Run by ctest stokes_lua_api; it
-- prints "stokes lua api: N checks ok" or stops at the first mismatch.
local n = 0
local function expect_error(pattern, f, ...)
  local ok, msg = pcall(f, ...)
  assert(not ok, string.format("expected an error matching %q, the call succeeded", pattern))
  local want = "lua_api%.lua:%d+: " .. pattern
  assert(tostring(msg):find(want), string.format("message %q does not match %q", tostring(msg), want))
  n = n + 1
end
local function check(cond, what)
  assert(cond, what)
  n = n + 1
end

local w = porelab.world { gravity = { 0, -9.8 }, dt = 1e-4 }
local m = w:material { name = "grain", density = 2000, kn = 1e6 }
-- before the fluid exists
expect_error("stokes_solve: the world has no Stokes fluid", w.stokes_solve, w)
-- each field out of its range, of the wrong type, or unknown
expect_error("stokes: viscosity must be a number in %[1e%-30, 1e%+30%] Pa s %(got %-1%)", w.stokes, w, { viscosity = -1 })
expect_error("stokes: density must be a number in %[0, 1e%+30%] kg/m%^3 %(got %-5%)", w.stokes, w, { density = -5 })
expect_error("stokes: disc_elements must be an integer in %[6, 4096%] elements %(got 2%)", w.stokes, w, { disc_elements = 2 })
expect_error("stokes: disc_elements must be an integer", w.stokes, w, { disc_elements = 12.5 })
expect_error("stokes: wall_elements must be an integer in %[1, 100000%] elements %(got 0%)", w.stokes, w, { wall_elements = 0 })
expect_error("stokes: polygon_elements must be an integer in %[3, 4096%]", w.stokes, w, { polygon_elements = 1 })
expect_error("stokes: element_length must be a number in %[0, 1e%+30%] m", w.stokes, w, { element_length = -0.1 })
expect_error("stokes: gap must be a number %(got string%)", w.stokes, w, { gap = "wide" })
expect_error("stokes: gap must be a number in %[0, 1e%+30%] m", w.stokes, w, { gap = -1e-3 })
expect_error("stokes: solve_every must be an integer in %[1, 1e%+06%] steps %(got 0%)", w.stokes, w, { solve_every = 0 })
expect_error("stokes: field_grid must be an integer in %[2, 1000%] points %(got 1%)", w.stokes, w, { field_grid = 1 })
expect_error("stokes: check_stability must be", w.stokes, w, { check_stability = 3 })
expect_error("stokes: load_contacts must be", w.stokes, w, { load_contacts = 2 })
expect_error("stokes: viscosity must be a number", w.stokes, w, { viscosity = 0 / 0 })
expect_error("stokes: unknown field 'viscosty' %(valid: viscosity, density", w.stokes, w, { viscosty = 1 })
local other = porelab.world {}
local om = other:material { name = "x", density = 1000, kn = 1e6 }
local ow = other:wall { from = { 0, 0 }, to = { 1, 0 }, material = om }
expect_error("stokes: load_wall is a body of another world", w.stokes, w, { load_wall = ow })

-- a box and a disc; the fluid attached
local bottom = w:wall { from = { -0.1, 0 }, to = { 1.1, 0 }, material = m }
local right = w:wall { from = { 1, -0.1 }, to = { 1, 1.1 }, material = m }
local top = w:wall { from = { 1.1, 1 }, to = { -0.1, 1 }, material = m }
local left = w:wall { from = { 0, 1.1 }, to = { 0, -0.1 }, material = m }
local d = w:disc { center = { 0.5, 0.5 }, radius = 0.1, material = m }
local def = w:stokes { viscosity = 0.5, density = 1000, disc_elements = 16, wall_elements = 8 }
check(def.viscosity == 0.5 and def.disc_elements == 16 and def.gap == 0 and def.load_wall == -1, "w:stokes returns the def")
check(w:stokes().viscosity == 0.5, "w:stokes() reads the def")
expect_error("stokes_body: no solve yet", w.stokes_body, w, d)
w:stokes_solve()
local r = w:stokes_body(d)
check(type(r.drag) == "table" and #r.drag == 2 and type(r.moment) == "number", "stokes_body: drag and moment")
-- at rest: no drag; buoyancy rho_l A g upwards; a finite stable step
check(math.abs(r.drag[1]) < 1e-9 and math.abs(r.drag[2]) < 1e-9, "a disc at rest in fluid at rest feels no drag")
check(math.abs(r.buoyancy[2] - 1000 * math.pi * 0.01 * 9.8) < 1e-9, "buoyancy rho_l A g")
check(r.k > 0 and r.k_rot > 0 and r.dt_safe > 0 and r.dt_safe < math.huge, "resistances and the stable step")
local vx, vy, p = w:stokes_point(0.2, 0.8)
check(vx == 0 and vy == 0 and type(p) == "number", "stokes_point in the fluid")
local none, why = w:stokes_point(0.5, 0.5)
check(none == nil and why == "the point is not in the fluid", "stokes_point inside the disc")
none, why = w:stokes_point(2, 2)
check(none == nil and why == "the point is not in the fluid", "stokes_point outside the container")
check(type(w:stokes_wall_pressure(bottom)) == "number", "wall pressure of a side")
check(w:stokes_wall_pressure(d) ~= w:stokes_wall_pressure(d), "wall pressure of a disc is NaN")
-- a held wall must be one of the container's sides (refused at the solve, naming the body)
w:stokes { load_wall = d, load_force = 10 }
expect_error("stokes_solve: stokes: load_wall %d+ is not one of the container.s wall segments", w.stokes_solve, w)
-- a held wall: its pressure is the set force over its length
w:stokes { load_wall = top, load_force = 10 }
w:stokes_solve()
check(math.abs(w:stokes_wall_pressure(top) - 10) < 1e-6 and math.abs(w:stokes_wall_pressure(bottom) - 10) < 1e-3,
      "held wall: uniform pressure load_force / length")
-- a moving disc drags the fluid: the drag opposes the motion
d:set_velocity(0.01, 0)
w:stokes { load_wall = -1, load_force = 0 }
w:stokes_solve()
check(w:stokes_body(d).drag[1] < 0, "drag against the motion")
print(string.format("stokes lua api: %d checks ok", n))
