-- nasty: write_vtk into '.' (issue 13 item 4)
local w = porelab.world { gravity = { 0, -9.81 } }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5 }
w:disc { center = { 0, 0 }, radius = 0.1, material = m }
w:write_vtk('.')
return { world = w }
