-- An imperative scene: it builds a world, steps it itself, queries it, checks a result
-- with assert and writes a CSV. `porelab run` exits non-zero when an assert fails.
--   porelab run scenes/examples/imperative.lua     (CSV in out/imperative/bounce.csv)
--
-- A disc thrown at a wall with a contact dashpot chosen from a restitution coefficient
-- e = 0.5 must rebound with 0.5 times its impact speed (linear spring-dashpot:
-- e = exp(-pi zeta / sqrt(1 - zeta^2)), seed 003 §2.2.4). Gravity is off so that the
-- speeds before and after the contact are exactly the impact and rebound speeds.
local e = 0.5
local w = porelab.world { gravity = { 0, 0 }, dt = 1e-4 }
local m = w:material { name = "ball", density = 1000, kn = 1e6, friction = 0, restitution = e }
w:wall { from = { -1, 0 }, to = { 1, 0 }, material = m }
local ball = w:disc { center = { 0, 0.5 }, radius = 0.05, material = m, velocity = { 0, -3 } }

local csv = porelab.csv("bounce.csv", { "t", "y", "vy", "contacts" })
local v_in, v_out
local was_touching, vy_before = false, 0
while w:time() < 0.4 do
  w:step(10)
  local _, y = ball:position()
  local _, vy = ball:velocity()
  local touching = w:contact_count() > 0
  csv:row(w:time(), y, vy, w:contact_count())
  -- speeds from the last sample before the first contact and the first one after it
  if touching and not was_touching and not v_in then v_in = -vy_before end
  if was_touching and not touching and v_in and not v_out then v_out = vy end
  was_touching, vy_before = touching, vy
end
csv:close()

assert(v_in and v_out, "the ball never bounced")
local ratio = v_out / v_in
print(string.format("impact %.4f m/s, rebound %.4f m/s, ratio %.4f (e = %.2f)", v_in, v_out,
                    ratio, e))
-- Time discretisation (about 90 steps per contact) leaves an error well below 1%.
assert(math.abs(ratio - e) < 0.01 * e,
       string.format("rebound ratio %.4f differs from e = %.2f by more than 1%%", ratio, e))
