-- w:save / porelab.load / w:load (restart files from a scene, issue 12): step K, save, step on
-- to N; a second world built the same way loads the file and steps to N: the same hash. Paths
-- outside the output folder are refused in the sandbox; a file that is not a state is refused.
local packing = require "porelab.packing"

local function build()
  local w = porelab.world { gravity = { 0, -9.81 }, rayleigh_alpha = 20 }
  local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.2 }
  w:wall { from = { -0.005, 0 }, to = { 0.045, 0 }, material = sand }
  w:wall { from = { 0, 0 }, to = { 0, 0.3 }, material = sand }
  w:wall { from = { 0.04, 0 }, to = { 0.04, 0.3 }, material = sand }
  packing.rain(w, { lo = { 0.001, 0.002 }, hi = { 0.039, 0.05 }, radii = { 0.0020, 0.0026 },
                    count = 40, material = sand, seed = 3 })
  w:fluid_quad { corners = { { 0, 0 }, { 0.04, 0 }, { 0.04, 0.08 }, { 0, 0.08 } }, ndivx = 4, ndivy = 8 }
  w:fluid_bc { from = { 0, 0 }, to = { 0.04, 0 }, head = 0.09 }
  w:fluid_bc { from = { 0, 0.08 }, to = { 0.04, 0.08 }, head = 0.08 }
  w:set_flag("FLUIDS_ON", 1)
  w:set_flag("FLUID_PERM", 1)
  w:set_flag("FLUID_STORAGE", 1)
  w:set_flag("FIRST_STEP_STATIC", 0)
  w:set_flag("FLUID_SOLVE_TIMESTEPS", 3)
  return w
end

local K, N = 400, 1000
local a = build()
a:step(K)
local hk = a:hash()
local path = a:save("state_lua.plstate")
assert(path:match("state_lua%.plstate$"), path)
a:step(N - K)
local hn = a:hash()

local b = build()
assert(b:hash() ~= hk)
porelab.load(b, "state_lua.plstate")
assert(b:steps() == K, "loaded world is at step " .. b:steps())
assert(b:hash() == hk)
b:step(N - K)
assert(b:hash() == hn, "resumed hash differs")

local c = build()
c:step(17)
c:load("state_lua.plstate")
c:step(N - K)
assert(c:hash() == hn)

local ok, err = pcall(function() b:save("/tmp/porelab_state_outside.plstate") end)
assert(not ok and err:match("save: writing .* is not allowed in a sandboxed scene"), tostring(err))
ok, err = pcall(function() porelab.load(b, "../outside.plstate") end)
assert(not ok and err:match("load"), tostring(err))
local f = io.open("not_a_state.plstate", "w")
f:write("hello, this is not a state file and it is long enough to hold a header......\n")
f:close()
ok, err = pcall(function() b:load("not_a_state.plstate") end)
assert(not ok and err:match("not a porelab state file"), tostring(err))
print("state.lua: " .. string.format("%s", hn) .. " ok; refused: " .. err)
