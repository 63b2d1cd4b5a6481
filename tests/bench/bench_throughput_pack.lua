-- Benchmark packing for tests/bench/bench_throughput.sh: 3,000 discs of two sizes rained into a
-- box of three walls, 1 s of settling; run by porelab and, exported (porelab export-lammps), by
-- LAMMPS in serial and with mpirun -np 2.
local packing = require "porelab.packing"

local w = porelab.world { gravity = { 0, -9.81 }, dt_safety = 0.2 }
local sand = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5, restitution = 0.4 }
local steel = w:material { name = "steel", density = 7800, kn = 1e6, friction = 0.5, restitution = 0.4 }
packing.box(w, { lo = { 0, 0 }, hi = { 0.6, 0.8 }, material = steel })
packing.rain(w, { lo = { 0.006, 0.006 }, hi = { 0.594, 0.6 }, radii = { 0.004, 0.005 },
                  count = 3000, material = sand, seed = 5 })
return { world = w, run = { t_end = 1.0, fps = 2 } }
