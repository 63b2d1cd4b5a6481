-- ctest soil_simple_shear / soil_simple_shear_full (docs/soil.md §4, §5.4): runs
-- scenes/soil/simple_shear.lua and checks the undrained-equals-constant-volume criterion:
-- at every checkpoint (strains 2..12.5 % monotonic; each cycle's positive peak and end, cyclic)
-- the pore-pressure rise of the sealed saturated sample equals the drop of the vertical
-- effective stress of the dry constant-volume sample within TOL sigma'_v0, and over the whole
-- record rms(du - drop) <= TOL_RMS sigma'_v0. Measured (default run): worst point 0.005,
-- rms 0.003 (cyclic) and 0.012 / 0.004 (monotonic); the tolerance was set at twice the worst
-- measured with an earlier build (0.023) and kept: the uncoupled run's worst point is 0.114.
-- Needs --trust (it loads the scene from another folder). SIMPLE_SHEAR may be preset by a
-- wrapper (the short version below sets it).
SIMPLE_SHEAR = SIMPLE_SHEAR or {}
local TOL, TOL_RMS = 0.05, 0.03
local scene = dofile(porelab.scene_dir .. "/../../scenes/soil/simple_shear.lua")
local finish = scene.on_finish
scene.on_finish = function(w)
  finish(w)
  local R = SIMPLE_SHEAR_RESULT
  assert(R and #R.rows > 0, "simple_shear: no result")
  for _, row in ipairs(R.rows) do
    assert(#row.points > 0, row.kind .. ": no checkpoints")
    local worst, seen = 0, 0
    for _, p in ipairs(row.points) do
      local d = math.abs(p.du - p.drop) / row.sv0
      worst = math.max(worst, d)
      seen = math.max(seen, math.abs(p.drop) / row.sv0)
    end
    print(string.format("check %s: worst |du - drop| = %.3f sigma'_v0 (tolerance %.2f), rms %.3f (tolerance %.2f), largest drop %.3f sigma'_v0",
      row.kind, worst, TOL, row.rms / row.sv0, TOL_RMS, seen))
    -- a part of a row of docs/validation.md (tests/harness.h: pl_validation; ctest label validation-doc)
    print(string.format("VALIDATION|%s|undrained constant-volume simple shear (Tan 1990 §5.4–5.6, "
      .. "20 discs%s)|Δu = drop of σ'_v in the dry constant-volume run|worst %.2f σ'_v0, rms %.2f|%s: worst %.3f, "
      .. "rms %.3f σ'_v0", SIMPLE_SHEAR.cycles and "soil.simple_shear_short" or "soil.simple_shear", SIMPLE_SHEAR.cycles and (", " .. SIMPLE_SHEAR.cycles
      .. " cycles") or "", TOL, TOL_RMS, row.kind, worst, row.rms / row.sv0))
    -- the check means something only if the skeleton did lose effective stress
    assert(seen > 0.1, row.kind .. ": the dry constant-volume sample hardly changed (" .. seen .. ")")
    assert(worst <= TOL, string.format("%s: du differs from the drop of sigma'_v by %.3f sigma'_v0", row.kind, worst))
    assert(row.rms / row.sv0 <= TOL_RMS, string.format("%s: rms(du - drop) = %.3f sigma'_v0", row.kind, row.rms / row.sv0))
  end
  print("simple_shear check: PASS")
end
return scene
