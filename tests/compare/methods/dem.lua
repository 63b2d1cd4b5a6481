-- Method: the grain engine (engine/src/dem): linear spring-dashpot contacts integrated by the
-- damped central difference scheme. Resolution knob: the time step as a fraction of the
-- critical step the engine computes (world{dt_safety = ...}; default 0.1).
local ladder = { 0.5, 0.3, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005 }
local function attach(_, _, safety) return { dt_safety = safety } end

return {
  name = "dem",
  label = "grain engine, central difference",
  model = "dem",
  problems = {
    restitution = { knob = "\u{0394}t / critical step", unit = "1", values = ladder, attach = attach },
    energy = { knob = "\u{0394}t / critical step", unit = "1", values = ladder, attach = attach },
  },
}
