-- Many VTK frames (--vtk): the .pvd collections, rewritten at every frame, grow past a few KB (about 70
-- bytes a frame) while each frame's files stay small. Under a small file size limit its
-- rewrite fails, and no truncated .pvd may be left under its final name.
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.04, material = m }
return { world = w, run = { steps = 400, every = 1 }, render = { size = { 16, 16 } } }
