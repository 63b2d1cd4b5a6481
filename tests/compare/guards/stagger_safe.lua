-- Below the staggering limit: the same box with K_f = 1e5 Pa and the fluid solved every step
-- runs to the end (tests/compare/guards/stagger.lua is the one past the limit).
local KF, EVERY = 1e5, 1
local w = porelab.world { gravity = { 0, 0 }, dt = 1e-4 }
local m = w:material { name = "grain", density = 2650, kn = 100, friction = 0.3 }
local L = 0.04
w:wall { from = { 0, 0 }, to = { L, 0 }, material = m }
w:wall { from = { L, 0 }, to = { L, L }, material = m }
w:wall { from = { L, L }, to = { 0, L }, material = m }
w:wall { from = { 0, L }, to = { 0, 0 }, material = m }
for i = 0, 3 do
  for j = 0, 3 do
    w:disc { center = { 0.005 + 0.01 * i, 0.005 + 0.01 * j }, radius = 0.004, material = m }
  end
end
w:fluid_quad { corners = { { 0, 0 }, { L, 0 }, { L, L }, { 0, L } }, ndivx = 8, ndivy = 8 }
w:darcy { on = true, consolidation = true, bulk_modulus = KF, storage = 0, perm_mode = 0,
          perm_high = 1e-4, solve_every = EVERY }
return { world = w, run = { steps = 200, every = 1000 } }
