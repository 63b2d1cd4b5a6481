-- ctest soil_consolidation_short (default set, ~20 s): the consolidation scene with ONE column.
-- A single column of 130 grains is one sample of a heterogeneous skeleton: over twelve columns
-- its U(T_v = 0.1) scattered from -13% to +12% about Terzaghi's (docs/soil.md §5.2), so this
-- check uses 20%: it catches a broken coupling (without it U is ~1 at once) or a broken
-- analysis, not the 5% of the issue, which the four-column run (soil_consolidation, long)
-- checks.
CONSOLIDATION = { columns = 1, tol = 0.20 }
return dofile(porelab.scene_dir .. "/../../scenes/soil/consolidation.lua")
