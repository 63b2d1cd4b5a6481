-- nasty: unknown flags and flags with wrong values
local w = porelab.world {}
w:set_flag("NO_SUCH_FLAG", 1)
return { world = w }
