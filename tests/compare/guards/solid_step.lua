-- Past the explicit solid's critical step: the cantilever of tests/compare/stability/solid_step.lua
-- (critical step 1.09e-6 s) with dt = 2e-6 s. The solid refuses the step and names the element
-- and the safe step.
local w = porelab.world { gravity = { 0, 0 }, dt = 2e-6 }
w:solid { young = 2e11, poisson = 0.3, density = 7800, formulation = "plain" }
w:solid_rectangle { x0 = 0, y0 = 0, x1 = 0.1, y1 = 0.02, nx = 10, ny = 2 }
w:solid_fix { box = { -1e-6, -1e-6, 1e-6, 0.02 + 1e-6 }, x = true, y = true }
w:solid_initial_velocity { box = { 1e-6, -1, 1, 1 }, vy = 0.1 }
return { world = w, run = { steps = 20, every = 1000 } }
