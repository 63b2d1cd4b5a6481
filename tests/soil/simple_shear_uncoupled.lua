-- ctest soil_simple_shear_uncoupled: the same short run with FLUID_CONSOLIDATION 0. The water
-- then does not respond to the skeleton's volume change, the undrained lid settles like the
-- drained one, and the criterion of simple_shear_check.lua must FAIL: this run passes only if
-- the pore-pressure rise stays far from the constant-volume drop (worst point > 0.1 sigma'_v0)
-- while that drop is large. So the check in simple_shear_check.lua fails when the coupling breaks.
SIMPLE_SHEAR = { rows = "cyclic", cycles = 3, coupling = false }
local scene = dofile(porelab.scene_dir .. "/../../scenes/soil/simple_shear.lua")
local finish = scene.on_finish
scene.on_finish = function(w)
  finish(w)
  local row = SIMPLE_SHEAR_RESULT.rows[1]
  local worst, seen, umax = 0, 0, 0
  for _, p in ipairs(row.points) do
    worst = math.max(worst, math.abs(p.du - p.drop) / row.sv0)
    seen = math.max(seen, math.abs(p.drop) / row.sv0)
    umax = math.max(umax, math.abs(p.du) / row.sv0)
  end
  print(string.format("uncoupled: worst |du - drop| = %.3f sigma'_v0, largest |du| %.3f, largest drop %.3f", worst, umax, seen))
  -- the row of docs/validation.md (tests/harness.h: pl_validation; ctest label validation-doc)
  print(string.format("VALIDATION|soil.simple_shear_uncoupled|same with the coupling off (FLUID_CONSOLIDATION 0)|"
    .. "must fail the criterion|worst > 0.1 σ'_v0|worst %.3f σ'_v0", worst))
  assert(seen > 0.1, "the dry constant-volume sample hardly changed")
  assert(worst > 0.1, "without the coupling the criterion should fail, but |du - drop| <= 0.1 sigma'_v0")
  print("simple_shear uncoupled: the criterion fails as it must: PASS")
end
return scene
