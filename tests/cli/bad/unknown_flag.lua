-- bad input: a flag that does not exist
local w = porelab.world {}
w:set_flag("TIMESTEP", 100)
return w
