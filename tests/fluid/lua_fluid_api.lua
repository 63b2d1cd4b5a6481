-- Lua-level test of the fluid binding (lua/wrap_fluid.c) and the MIMES compatibility module
-- (lua/lib/porelab/mimes.lua); an imperative script: any failed check raises, and porelab
-- exits non-zero. Run by ctest as fluid_lua_api (tests/fluid/tests.cmake).
local mimes = require "porelab.mimes"

local function check(cond, fmt, ...)
  if not cond then error(string.format(fmt, ...), 2) end
end

-- 1. dam flow (seed 000 Appendix C.1) through the MIMES commands: inflow = outflow
local M = mimes.session()
M.install(_ENV)
add_fluid_mesh_ui(50, 50, 250, 50, 250, 300, 50, 300, 4, 4, 1000)
add_fluid_mesh_ui(250, 50, 350, 50, 350, 100, 250, 100, 4, 4, 1001)
add_fluid_mesh_ui(350, 50, 480, 50, 480, 300, 350, 300, 4, 4, 1002)
add_fluid_bc_ui(50, 300, 250, 300, 40)
add_fluid_bc_ui(350, 300, 480, 300, 0)
set("FLUID_PERM", 0)
set("FLUID_PERM_HIGH", 5.0)
set("FLUID_DENSITY", 0.1)
set("E(1)", 200)
check(M.get("matnum") == nil, "plain variables start unset")
apply_mimes_params()
local w = M.world
w:fluid_solve_static()
local qin, qout = w:fluid_line_inflow(1), w:fluid_line_inflow(2)
check(qin > 0 and math.abs(qin + qout) <= 1e-8 * qin, "inflow %g, outflow %g", qin, -qout)
check(#w:fluid_nodes() == 121 and #w:fluid_triangles() == 200, "dam mesh %d nodes, %d triangles",
      #w:fluid_nodes(), #w:fluid_triangles())
local head = w:fluid_node_field("head")
check(#head == 121, "head field length %d", #head)
local vx = w:fluid_element_field("vx")
check(#vx == 200, "vx length %d", #vx)
check(w:fluid_pressure_at(0, 0) == nil, "pressure outside the mesh must be nil")
local p = w:fluid_pressure_at(300, 60)
check(p and p > 0, "pressure under the dam %s", tostring(p))
change_fluid_id_ui(1001, 2001)
local ok, err = pcall(change_fluid_id_ui, 1001, 5)
check(not ok and err:find("no fluid quad has id 1001"), "change_fluid_id error: %s", tostring(err))

-- 2. native API: a clockwise quad is refused with a message that says so
ok, err = pcall(function() w:fluid_quad { corners = { { 0, 0 }, { 0, 1 }, { 1, 1 }, { 1, 0 } } } end)
check(not ok and err:find("clockwise"), "clockwise quad: %s", tostring(err))
ok, err = pcall(function() w:fluid_quad { corners = { { 0, 0 }, { 1, 0 } } } end)
check(not ok and err:find("4 vectors"), "corners check: %s", tostring(err))
ok, err = pcall(function() w:fluid_bc { from = { 0, 0 }, to = { 1, 0 }, hed = 1 } end)
check(not ok and err:find("unknown field"), "field typo: %s", tostring(err))

-- 3. native API: Archimedes on a rectangle in still water, rho_f = 1000, g = 9.81
local v = porelab.world { gravity = { 0, -9.81 } }
v:fluid_quad { corners = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, ndivx = 5, ndivy = 5 }
v:fluid_bc { from = { 0, 0 }, to = { 1, 0 }, head = 1 }
v:fluid_bc { from = { 0, 1 }, to = { 1, 1 }, head = 0 }
v:set_flag("FLUID_DENSITY", 1000)
local m = v:material { name = "wood", density = 500, kn = 1e5 }
local b = v:rectangle { center = { 0.43, 0.37 }, width = 0.2, height = 0.1, angle = 0.3, material = m, fixed = true }
v:fluid_solve_static()
local fx, fy, mz = v:fluid_body_force(b)
check(math.abs(fy - 1000 * 9.81 * 0.02) <= 1e-9 * 196.2 and math.abs(fx) < 1e-8 and math.abs(mz) < 1e-8,
      "Archimedes: F = (%g, %g), M = %g; expected (0, 196.2), 0", fx, fy, mz)
local st = v:fluid_stats()
check(st.factorizations == 1 and st.analyses == 1, "stats: %d factorizations, %d analyses",
      st.factorizations, st.analyses)
print(string.format("fluid Lua API: dam inflow %.10g = outflow %.10g; Archimedes F_y = %.10g N", qin, -qout, fy))
