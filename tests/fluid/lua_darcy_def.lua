-- The Darcy model's typed def and the MIMES flags are one storage, read and checked through one
-- parameter table (porelab/darcy.h): w:darcy{...} sets flags, set_flag shows in w:darcy(), and
-- a bad value is refused with the field's range, from Lua and from the flag alike.
local w = porelab.world {}
local d = w:darcy { on = true, solve_every = 20, density = 1025, consolidation = 1 }
assert(d.on == 1 and d.solve_every == 20 and d.density == 1025 and d.consolidation == 1)
assert(w:flag("FLUIDS_ON") == 1 and w:flag("FLUID_SOLVE_TIMESTEPS") == 20)
assert(w:flag("FLUID_DENSITY") == 1025 and w:flag("FLUID_CONSOLIDATION") == 1)
w:set_flag("FLUID_PERM_HIGH", 3)
assert(w:darcy().perm_high == 3)
-- defaults come from the same table as the flags' defaults
local fresh = porelab.world {}:darcy()
assert(fresh.on == 0 and fresh.perm_high == 5 and fresh.storage == 1e-4 and fresh.bulk_modulus == 2.2e9)
local function refused(f, pattern)
  local ok, e = pcall(f)
  assert(not ok, "accepted: " .. pattern)
  assert(tostring(e):find(pattern), tostring(e))
  assert(tostring(e):find("lua_darcy_def.lua:%d+:"), "no file:line in " .. tostring(e))
end
refused(function() w:darcy { solve_every = 0 } end, "solve_every must be an integer in %[1, 2e%+09%]")
refused(function() w:darcy { solve_evry = 1 } end, "unknown field 'solve_evry'")
refused(function() w:darcy { method = 1.5 } end, "method must be an integer")
refused(function() w:darcy { density = 1 / 0 } end, "density must be a number in")
refused(function() w:set_flag("FLUID_METHOD", 1.5) end, "whole numbers")
-- a refused call changes nothing
assert(w:darcy().solve_every == 20)
