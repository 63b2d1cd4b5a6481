-- ctest cli_compare_terzaghi_grains_uncoupled: the grain-column method of the terzaghi problem
-- (tests/compare/methods/grain_column.lua) with the pore pressure not coupled to the skeleton's
-- volume change (FLUID_CONSOLIDATION 0). The water then never carries the load, u / u0 at the
-- sealed end stays near 0, and the 2 % criterion of the ctest cli_compare_terzaghi_grains must
-- fail: this run passes only if the error is above 50 %.
--   porelab run tests/compare/guards/grain_column_uncoupled.lua --trust
GRAIN_COLUMN = { coupling = false }
local problem = dofile(porelab.scene_dir .. "/../problems/terzaghi.lua")
local method = dofile(porelab.scene_dir .. "/../methods/grain_column.lua")
local n = 3
local value = problem.run(method, { value = n, index = 1 })
local ref = problem.reference.value
local err = math.abs(value - ref) / math.abs(ref)
print(string.format("grain_column uncoupled, %d discs across: u/u0 at the sealed end %.4g at T_v = 0.2, Terzaghi %.4f, "
                    .. "error %.3g", n, value, ref, err))
assert(err > 0.5, string.format("without the coupling the error should be far above 2 %%, but it is %.3g", err))
print("grain_column uncoupled: the criterion fails as it must: PASS")
