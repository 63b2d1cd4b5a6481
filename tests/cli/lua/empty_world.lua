-- A world with no bodies at all still runs and draws its frames (an empty picture), instead of
-- crashing in the renderer (found while building the cavity scene of scenes/navier_stokes).
local w = porelab.world { gravity = { 0, -9.81 }, dt = 1e-3 }
return { world = w, run = { t_end = 0.01, fps = 100 } }
