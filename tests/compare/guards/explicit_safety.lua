-- Past the explicit Darcy update's limit: FLUID_EXPLICIT_SAFETY above 1 would take sub-steps
-- longer than 2 / lambda_max(M^-1 K); the parameter table refuses it with the valid range.
local w = porelab.world { gravity = { 0, 0 } }
w:fluid_quad { corners = { { 0, 0 }, { 1, 0 }, { 1, 0.1 }, { 0, 0.1 } }, ndivx = 20, ndivy = 1 }
w:darcy { on = true, method = 2, explicit_safety = 1.5 }
return w
