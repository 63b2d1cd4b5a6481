-- nasty: NUL and newlines in names
local w = porelab.world {}
local m = w:material { name = 'sa\0nd\n', density = 2650, kn = 1e6 }
w:disc { center = { 0, 0 }, radius = 0.1, material = 'sa\0nd\n' }
return { world = w }
