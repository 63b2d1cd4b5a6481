-- Bad input for porelab export-lammps: discs with what gran/hooke/history cannot express
-- (bonds, rolling resistance, cohesion, a slanted wall, rotational global damping); the export
-- must list every one (tests/cli/lammps/tests.cmake, lammps_refuse_mix).
local w = porelab.world { gravity = { 0, -9.81 }, global_damping_rot = 0.01 }
local rock = w:material { name = "rock", density = 2650, kn = 1e6, friction = 0.5, rolling = 0.1, cohesion = 2 }
w:wall { from = { 0, 0 }, to = { 1, 0.2 }, material = rock }
w:disc { center = { 0.5, 0.3 }, radius = 0.05, material = rock }
w:disc { center = { 0.6, 0.3 }, radius = 0.05, material = rock }
w:bond_law { a = rock, b = rock, kn = 1e6, rn = 100, rt = 100 }
w:bond_touching(0.001)
return { world = w, run = { t_end = 0.1 } }
