-- porelab.mimes: the MIMES shell commands of seed 000 (Klosek 1997) Appendices B and C, so that
-- the thesis's Tcl problem files become Lua scenes line for line:
--
--   local mimes = require "porelab.mimes"
--   local M = mimes.session()          -- a world with MIMES defaults (gravity 0 until GRAVITY_Y)
--   M.install(_ENV)                    -- the commands become plain functions of the scene
--   set_scales_ui(0, 0, 600, 600)
--   add_fluid_mesh_ui(50, 50, 250, 50, 250, 300, 50, 300, 4, 4, 1000)
--   add_fluid_bc_ui(50, 300, 250, 300, 40)
--   set("FLUIDS_ON", 1)                -- Tcl: set FLUIDS_ON 1
--   set("E(1)", 200)                   -- Tcl: set E(1) 200   (arrays keep the Tcl syntax)
--   apply_mimes_params()
--   return M.scene()                   -- the declarative scene (TIMESTEPS, PRINT_INT, camera)
--
-- Commands: add_fluid_mesh_ui, add_fluid_bc_ui, clear_fluid_bcs_ui, change_fluid_id_ui,
-- add_rectangle_ui, add_superquad_ui, set_velocity, create_material_list_ui,
-- apply_material_list, apply_fric, apply_kn, apply_ks, set_scales_ui, set, global,
-- apply_mimes_params (alias apply_mines_params, as spelled in Appendix C.1/C.3).
-- Where the thesis does not give an argument order (add_superquad_ui, set_velocity) the
-- interpretation is written next to the function. Flags are applied in order by
-- apply_mimes_params, as in MIMES; EXODUS* output is replaced by VTK (.vtu) output.
local porelab = require "porelab"

local mimes = {}

local fail = require("porelab.check").for_module("")

local function nums(fn, n, ...)
  local a = table.pack(...)
  if a.n < n then fail(fn, "expects %d numbers (got %d)", n, a.n) end
  for i = 1, n do
    if type(a[i]) ~= "number" then fail(fn, "argument %d must be a number (got %s)", i, type(a[i])) end
  end
  return a
end

-- Counter-clockwise order of four corners (MIMES accepted either for rectangles).
local function ccw(v)
  local s = 0
  for i = 1, #v do
    local p, q = v[i], v[i % #v + 1]
    s = s + p[1] * q[2] - q[1] * p[2]
  end
  if s < 0 then
    local r = {}
    for i = #v, 1, -1 do r[#r + 1] = v[i] end
    return r
  end
  return v
end

-- Flags that carry strings or belong to output MIMES had and porelab replaces.
local string_flags = { FLUID_GEOMETRY_FILENAME = "geometry", FLUID_PRESSURES_FILENAME = "pressures" }
local aliases = { FLUID_PRESSES_FLAG = "FLUID_PRESSURES_FLAG" } -- spelling in Appendix C.2/C.3

function mimes.session(opts)
  opts = opts or {}
  local w = porelab.world { gravity = opts.gravity or { 0, 0 } }
  local M = { world = w }
  local arrays = {}       -- Tcl arrays: E, nu, density, fric, k_normal, k_shear, ...
  local vars = {}         -- other Tcl variables (matnum, ...)
  local pending = {}      -- flags waiting for apply_mimes_params, in order
  local materials = {}    -- MIMES material number -> porelab material
  local bodies = {}       -- MIMES id -> body
  local nmat = 0
  local scales = nil
  local exodus = { on = false, file = "mimes.vtu", step = 1 }

  local function material(i, fn)
    if materials[i] then return materials[i] end
    if i == 1 and nmat == 0 then
      -- MIMES scripts that never define materials use material 1 for fixed walls
      materials[1] = w:material { name = "mimes1", density = 1, kn = 1e5 }
      return materials[1]
    end
    fail(fn, "material %s is not defined (create_material_list_ui / apply_material_list)", tostring(i))
  end

  local function register(id, b)
    if bodies[id] then fail("add body", "id %d is already used", id) end
    bodies[id] = b
    return b
  end

  function M.set(name, value)
    if type(name) ~= "string" then fail("set", "the variable name must be a string") end
    local arr, key = name:match("^([%w_]+)%((.-)%)$")
    if arr then
      arrays[arr] = arrays[arr] or {}
      arrays[arr][key:gsub("%s", "")] = value
      return
    end
    name = aliases[name] or name
    if string_flags[name] then
      if type(value) ~= "string" then fail("set", "%s must be a file name", name) end
      pending[#pending + 1] = { name = name, value = value }
    elseif name == "EXODUSWRITEFILE" then
      exodus.file = tostring(value):gsub("%.exe$", ".vtu")
    elseif name == "EXODUSFLAG" then
      exodus.on = value ~= 0
    elseif name == "EXODUSOUTPUTSTEP" then
      exodus.step = value
    elseif name:match("^[A-Z][A-Z0-9_]*$") then
      if type(value) ~= "number" then fail("set", "flag %s takes a number (got %s)", name, type(value)) end
      pending[#pending + 1] = { name = name, value = value }
    else
      vars[name] = value
    end
  end

  function M.get(name) return vars[name] end
  function M.global() end -- Tcl 'global E(2)': nothing to do in Lua

  function M.apply_mimes_params()
    for _, p in ipairs(pending) do
      if string_flags[p.name] then
        w:fluid_output_file(string_flags[p.name], p.value)
      else
        w:set_flag(p.name, p.value)
      end
    end
    pending = {}
  end
  M.apply_mines_params = M.apply_mimes_params

  function M.set_scales_ui(x0, y0, x1, y1)
    nums("set_scales_ui", 4, x0, y0, x1, y1)
    scales = { x0, y0, x1, y1 }
  end

  -- add_fluid_mesh_ui x1 y1 x2 y2 x3 y3 x4 y4 ndivx ndivy id (Appendix B.1)
  function M.add_fluid_mesh_ui(...)
    local a = nums("add_fluid_mesh_ui", 11, ...)
    return w:fluid_quad { corners = { { a[1], a[2] }, { a[3], a[4] }, { a[5], a[6] }, { a[7], a[8] } },
                          ndivx = math.tointeger(a[9]) or a[9], ndivy = math.tointeger(a[10]) or a[10],
                          id = math.tointeger(a[11]) or a[11] }
  end

  -- add_fluid_bc_ui x1 y1 x2 y2 val: pressure head val on the nodes of the segment
  function M.add_fluid_bc_ui(...)
    local a = nums("add_fluid_bc_ui", 5, ...)
    return w:fluid_bc { from = { a[1], a[2] }, to = { a[3], a[4] }, head = a[5] }
  end

  -- porelab addition (eq. 3.14): add_fluid_flux_ui x1 y1 x2 y2 q (inflow, m/s)
  function M.add_fluid_flux_ui(...)
    local a = nums("add_fluid_flux_ui", 5, ...)
    return w:fluid_flux { from = { a[1], a[2] }, to = { a[3], a[4] }, inflow = a[5] }
  end

  function M.clear_fluid_bcs_ui() w:clear_fluid_bcs() end

  function M.change_fluid_id_ui(old, new)
    nums("change_fluid_id_ui", 2, old, new)
    w:change_fluid_id(math.tointeger(old), math.tointeger(new))
  end

  function M.create_material_list_ui(n)
    nums("create_material_list_ui", 1, n)
    nmat = n
  end

  -- apply_material_list n: materials 1..n from density(i), E(i) (Young's modulus), nu(i)
  function M.apply_material_list(n)
    nums("apply_material_list", 1, n)
    local dens, E = arrays.density or {}, arrays.E or {}
    for i = 1, n do
      local key = tostring(i)
      if not materials[i] then
        if not dens[key] then fail("apply_material_list", "density(%d) is not set", i) end
        if not E[key] then fail("apply_material_list", "E(%d) is not set", i) end
        materials[i] = w:material { name = "mimes" .. i, density = dens[key], young = E[key] }
      end
    end
  end

  local function apply_pair(fn, arr, field, n)
    nums(fn, 1, n)
    local t = arrays[arr] or {}
    for i = 1, n do
      for j = 1, i do
        local v = t[i .. "," .. j] or t[j .. "," .. i]
        if v then w:pair(material(i, fn), material(j, fn), { [field] = v }) end
      end
    end
  end
  function M.apply_fric(n) apply_pair("apply_fric", "fric", "friction", n) end
  function M.apply_kn(n) apply_pair("apply_kn", "k_normal", "kn", n) end
  function M.apply_ks(n) apply_pair("apply_ks", "k_shear", "ks", n) end

  -- add_rectangle_ui x1 y1 x2 y2 x3 y3 x4 y4 id mat (corners in either order)
  function M.add_rectangle_ui(...)
    local a = nums("add_rectangle_ui", 10, ...)
    local v = ccw { { a[1], a[2] }, { a[3], a[4] }, { a[5], a[6] }, { a[7], a[8] } }
    local b = w:polygon { vertices = v, material = material(a[10], "add_rectangle_ui"), id = math.tointeger(a[9]) }
    return register(a[9], b)
  end

  -- add_superquad_ui x1 y1 x2 y2 id mat n angle _ nverts vx vy
  -- Interpretation (the thesis lists the call, C.2, but not its signature): (x1, y1) and
  -- (x2, y2) are opposite corners of the bounding box, |x/a|^n + |y/b|^n = 1 with exponent n
  -- (n = 2: ellipse), angle in degrees, nverts outline vertices, initial velocity (vx, vy).
  function M.add_superquad_ui(...)
    local a = nums("add_superquad_ui", 12, ...)
    local cx, cy = (a[1] + a[3]) / 2, (a[2] + a[4]) / 2
    local ax, by = math.abs(a[3] - a[1]) / 2, math.abs(a[4] - a[2]) / 2
    local n, nv = a[7], math.max(8, math.floor(a[10]))
    if n < 1 then fail("add_superquad_ui", "the exponent must be >= 1 for a convex outline (got %g)", n) end
    local v = {}
    for k = 0, nv - 1 do
      local t = 2 * math.pi * k / nv
      local c, s = math.cos(t), math.sin(t)
      local x = ax * (c < 0 and -1 or 1) * math.abs(c) ^ (2 / n)
      local y = by * (s < 0 and -1 or 1) * math.abs(s) ^ (2 / n)
      v[#v + 1] = { cx + x, cy + y }
    end
    local b = w:polygon { vertices = v, material = material(a[6], "add_superquad_ui"), id = math.tointeger(a[5]),
                          angle = a[8] * math.pi / 180, velocity = { a[11], a[12] } }
    return register(a[5], b)
  end

  -- set_velocity fx fy fr vx vy omega id: prescribes the velocity of body id (the three flags
  -- select x, y and rotation; porelab prescribes all three, so the flags must be 1 1 1)
  function M.set_velocity(...)
    local a = nums("set_velocity", 7, ...)
    local b = bodies[a[7]]
    if not b then fail("set_velocity", "no body has id %s", tostring(a[7])) end
    if a[1] ~= 1 or a[2] ~= 1 or a[3] ~= 1 then
      fail("set_velocity", "only fully prescribed motion (flags 1 1 1) is supported (got %g %g %g)", a[1], a[2], a[3])
    end
    b:set_velocity(a[4], a[5], a[6])
  end

  function M.body(id) return bodies[id] end

  -- The declarative scene: TIMESTEPS steps, a frame every PRINT_INT steps, camera from
  -- set_scales_ui, and the fluid VTK file when EXODUSFLAG was set.
  function M.scene(extra)
    extra = extra or {}
    local steps = math.tointeger(w:flag("TIMESTEPS")) or 1
    local every = math.tointeger(w:flag("PRINT_INT")) or 1
    local s = { world = w, run = { steps = math.max(1, steps), every = math.max(1, every) } }
    s.render = extra.render or {}
    if scales and not s.render.camera then s.render.camera = scales end
    if extra.on_frame or exodus.on then
      local user = extra.on_frame
      s.on_frame = function(world, ...)
        if user then user(world, ...) end
        if exodus.on then world:fluid_write_vtu(exodus.file) end
      end
    end
    for k, v in pairs(extra) do
      if k ~= "render" and k ~= "on_frame" then s[k] = v end
    end
    return s
  end

  -- Puts the commands into env (normally the scene's _ENV) so that lines read as in Tcl.
  function M.install(env)
    for k, v in pairs(M) do
      if type(v) == "function" and k ~= "install" and k ~= "scene" then env[k] = v end
    end
    return M
  end

  return M
end

return mimes
