-- nasty: fluid with NaN parameters
local w = porelab.world { gravity = { 0, -9.81 } }
local ok = pcall(function() w:darcy { permeability = 0/0, viscosity = -1 } end)
w:set_flag('FLUIDFLAG', 1)
return { world = w }
