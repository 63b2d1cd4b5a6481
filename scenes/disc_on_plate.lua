-- Seed 003 (Tan 1990) §2.2.5.1, Table 2.1: one disc (R = 1 m, rho = 2400 kg/m^3, so
-- m = 7539.823 kg) resting on a plate under g = 10 m/s^2 with k_N = 1e7 N/m, no friction.
-- Four damping cases; the table's final contact force at t = 5 s should equal the weight
-- 75398.23 N (case 1 oscillates between 0 and twice the weight).
-- Note: in the extracted Table 2.1 the damping columns of cases 2 and 3 look swapped; the
-- text says case 2 uses the global dashpot only and that its damping is ten times smaller
-- than case 3's contact dashpot, so case 2: C = 1e4, case 3: c_N = 1e5. Case 4 adds up to
-- the critical damping 2 sqrt(k m) = 5.49e5 N s/m.
local case = 4 -- 1..4

local cases = {
  { cn = 0,   C = 0 },
  { cn = 0,   C = 1.0e4 },
  { cn = 1e5, C = 0 },
  { cn = 1e5, C = 4.5e5 },
}
local c = cases[case]

local w = porelab.world {
  gravity = { 0, -10 },
  dt = 1e-3,                  -- s (5000 steps to t = 5 s, as in the seed)
  global_damping = c.C,       -- N s/m
}
local rock = w:material { name = "rock", density = 2400, kn = 1e7, ks = 0, friction = 0,
                          cn = c.cn, cs = 0 }
w:wall { from = { -2, 0 }, to = { 2, 0 }, material = rock }
w:disc { center = { 0, 1 }, radius = 1, material = rock }

local log = porelab.csv("contact_force.csv", { "t", "fn" }, { "s", "N" })
local weight = 2400 * math.pi * 10

return {
  world = w,
  run = { t_end = 5.0, fps = 20 },
  render = { size = { 480, 360 }, camera = { -2.2, -0.5, 2.2, 2.5 },
             title = string.format("Disc on a plate, case %d", case) },
  on_frame = function(world)
    local cs = world:contacts()
    log:row(world:time(), cs[1] and cs[1].fn or 0)
  end,
  on_finish = function(world)
    local cs = world:contacts()
    local fn = cs[1] and cs[1].fn or 0
    print(string.format("case %d: contact force %.2f N, weight %.2f N, error %.4f %%",
                        case, fn, weight, 100 * math.abs(fn - weight) / weight))
  end,
}
