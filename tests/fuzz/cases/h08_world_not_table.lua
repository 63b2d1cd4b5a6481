-- nasty: the world constructor with a number
local w = porelab.world(42)
return { world = w }
