-- nasty: a known flag with a NaN value
local w = porelab.world {}
w:set_flag("TIMESTEPS", 0/0)
return { world = w }
