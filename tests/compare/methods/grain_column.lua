-- Method: Terzaghi consolidation measured on a column of saturated discs under a piston: the
-- grain engine for the skeleton, Darcy flow on a mesh over the grains for the water, coupled
-- by the pore pressure that the skeleton's volume change creates (FLUID_CONSOLIDATION 1,
-- docs/soil.md §2 and §5.2). Nothing about the skeleton is typed in: the column's constrained
-- modulus M, porosity n, Skempton's B and c_v come from its own loading, as in the soil scene
-- scenes/soil/consolidation.lua.
--
-- The column: N discs across (radius 2 mm, kn = 2e5 N/m, friction 0.3, 2650 kg/m^3) in a
-- hexagonal lattice of 2N + 1 rows (the bottom row on the floor; rows of N and N - 1 discs),
-- in a box with frictionless side walls, a rough floor and a rough guided piston (it moves only
-- vertically). No gravity: the effective stress is the piston's P0 everywhere, as Terzaghi
-- assumes (a rained random packing has layers whose stiffness varies by tens of per cent, and a
-- single such column's U scatters by up to 13 % about the series: docs/soil.md §5.2; the regular
-- lattice is one uniform skeleton, so what is left is the coupled solver's error).
--   1. Drained twin (an identical column, no water): the pre-load P0 = 3 kPa, then the
--      increment DP = 3 kPa; M = DP H / s_f from the increment's settlement s_f (H the column's
--      height under P0), n = 1 - (disc area) / (W H), B = 1 / (1 + n M / K_f) and
--      c_v = D M B / (rho_f g) (the fluid's compressibility included; with gravity off the
--      heads still convert with standard gravity, engine/src/fluid/darcy/darcy_world.c).
--   2. The consolidation column: the same pre-load (drained), then at t0 the increment DP with
--      the conductivity D = 1e-4 m/s and the coupling on; drained at the floor (a head line),
--      sealed at the piston (it reaches through the top of the mesh). At t0 + T_v H^2 / c_v the
--      excess pore pressure under the piston (the sealed end), mean of four points across,
--      divided by the initial one u0 = B DP, is the measured value.
-- Resolution knob: discs across the column (the column's height grows with it; the fluid
-- mesh's elements are two discs wide and about two discs tall; elements of one disc gave
-- +0.32 % and +0.57 % for 4 and 6 discs across, against +0.22 % and +0.04 %). The grain step is
-- 0.1 of the critical step: the values agree with 0.05 to 3e-5; at 0.2 the 6- and 8-disc
-- columns were 0.4 % off, and with a finer mesh or half the conductivity they grew unstable
-- (u up to 2 u0) without any guard stopping them. Halving or doubling D moves the values by at
-- most 0.2 % (the piston's ringing at the start).
--
-- A test may set the global GRAIN_COLUMN = { coupling = false } to run the same column with
-- the pore pressure not coupled to the skeleton (tests/compare/guards/grain_column_uncoupled.lua).
local opt = rawget(_G, "GRAIN_COLUMN") or {}
local R = 0.002                 -- disc radius, m
local P0, DP = 3000, 3000       -- pre-load and increment, Pa
local D = 1e-4                  -- hydraulic conductivity during the increment, m/s
local KF = 1e6                  -- fluid bulk modulus, Pa (about 5-10 times M)
local RHO_F, G = 1000, 9.80665  -- water density, kg/m^3; standard gravity for heads, m/s^2
local T_SEAT = 0.1              -- s under the pre-load before the increment (the column at rest)
local PH = 6 * R                -- piston height, m

-- The column of n discs across; returns the world, the piston, the discs' area (m^2) and the
-- width W (m).
local function column(n)
  local w = porelab.world { gravity = { 0, 0 }, rayleigh_alpha = 20, dt_safety = 0.1, local_damping = 0.3 }
  local sand = w:material { name = "sand", density = 2650, kn = 2e5, friction = 0.3, restitution = 0.2 }
  local wall = w:material { name = "wall", density = 2650, kn = 2e5, friction = 0.0, restitution = 0.2 }
  local pmat = w:material { name = "piston", density = 1000, kn = 2e5, friction = 0.3, restitution = 0.2 }
  local W, dy, rows = 2 * n * R, math.sqrt(3) * R, 2 * n + 1
  w:wall { from = { -0.005, 0 }, to = { W + 0.005, 0 }, material = sand }
  w:wall { from = { 0, 0 }, to = { 0, 1 }, material = wall }
  w:wall { from = { W, 0 }, to = { W, 1 }, material = wall }
  local area = 0
  for j = 0, rows - 1 do
    local odd = j % 2 == 1
    for i = 0, odd and n - 2 or n - 1 do
      w:disc { center = { (odd and 2 * R or R) + 2 * R * i, R + j * dy }, radius = R, material = sand }
      area = area + math.pi * R * R
    end
  end
  local top = 2 * R + (rows - 1) * dy
  local piston = w:rectangle { center = { W / 2, top + PH / 2 }, width = W - 0.0006, height = PH,
                               material = pmat, guide = { 0, 1 } }
  piston:set_load(0, -P0 * W)
  return w, piston, area, W
end

local function piston_y(p) return select(2, p:position()) end

-- Drained twin: the skeleton's response to the increment without water.
local function skeleton(n)
  local w, piston, area, W = column(n)
  w:run_until(T_SEAT)
  local y0 = piston_y(piston)
  piston:set_load(0, -(P0 + DP) * W)
  -- at rest when the settlement changes by less than 1e-5 of itself in 0.02 s
  local s, t = 0, T_SEAT
  repeat
    local before = s
    t = t + 0.02
    w:run_until(t)
    s = y0 - piston_y(piston)
    assert(t < T_SEAT + 2, "grain_column: the drained column did not come to rest in 2 s")
  until math.abs(s - before) < 1e-5 * s
  local H = y0 - PH / 2
  local r = { H = H, sf = s, M = DP * H / s, n = 1 - area / (W * H) }
  r.B = 1 / (1 + r.n * r.M / KF)
  r.cv = D * r.M * r.B / (RHO_F * G)
  return r
end

local function measure(ctx, n)
  local sk = skeleton(n)
  local w, piston, _, W = column(n)
  local top = piston_y(piston)
  w:fluid_quad { corners = { { 0, 0 }, { W, 0 }, { W, top }, { 0, top } }, ndivx = math.max(1, n // 2),
                 ndivy = math.floor(top / (4 * R) + 0.5) }
  w:fluid_bc { from = { 0, 0 }, to = { W, 0 }, head = 0 }
  w:set_flag("FLUID_PERM", 0)
  w:set_flag("FLUID_STORAGE", 0)
  w:set_flag("FLUID_BULK_MODULUS", KF)
  w:set_flag("FLUID_SOLVE_TIMESTEPS", 1)
  -- the pre-load needs no water: without gravity and drained it carries no pressure
  w:run_until(T_SEAT)
  w:set_flag("FLUIDS_ON", 1)
  w:set_flag("FLUID_PERM_HIGH", D)
  w:set_flag("FLUID_CONSOLIDATION", opt.coupling == false and 0 or 1)
  piston:set_load(0, -(P0 + DP) * W)
  w:soil_reset()
  w:run_until(T_SEAT + ctx.Tv * sk.H * sk.H / sk.cv)
  local face, u = piston_y(piston) - PH / 2, 0
  for k = 1, 4 do u = u + w:fluid_pressure_at(W * (k - 0.5) / 4, face) / 4 end
  return u / (sk.B * DP)
end

return {
  name = "grain_column",
  label = "grain column under a piston, Darcy consolidation",
  model = "dem+darcy",
  problems = {
    terzaghi = { knob = "discs across the column", unit = "1", values = { 3, 4, 6, 8, 12 }, measure = measure },
  },
}
