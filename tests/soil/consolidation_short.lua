-- ctest soil_consolidation_short (default set, ~20 s): the consolidation scene with ONE column.
-- A single column of 130 grains is one sample of a heterogeneous skeleton: over twelve columns
-- its U(T_v = 0.1) scattered from -13% to +12% about Terzaghi's (docs/soil.md §5.2), so this
-- check uses 20%: it catches a broken coupling (without it U is ~1 at once) or a broken
-- analysis, not the 5% of the issue, which the four-column run (soil_consolidation, long)
-- checks.
-- The piston is an oedometer's guided piston (issue 13 item 11): it must not turn and must not
-- enter the side walls. Before it was guided it tilted 3-5 degrees and a corner entered a wall.
CONSOLIDATION = { columns = 1, tol = 0.20 }
local scene = dofile(porelab.scene_dir .. "/../../scenes/soil/consolidation.lua")
local w = scene.world
local walls, pistons = {}, {}
for i = 1, w:body_count() do
  local b = w:body(i)
  if b:shape() == "wall" then
    local v = b:vertices()
    if v[1][1] == v[2][1] then walls[#walls + 1] = v[1][1] end -- the vertical side walls
  elseif b:shape() == "polygon" then
    pistons[#pistons + 1] = b
  end
end
assert(#pistons == 1 and #walls == 2, "consolidation_short: expected one piston and two side walls")
local tilt, inside = 0, math.huge -- largest |angle| (deg); smallest corner clearance to a wall (m)
local frame, finish = scene.on_frame, scene.on_finish
scene.on_frame = function(world, ...)
  if frame then frame(world, ...) end
  for _, p in ipairs(pistons) do
    if p:motion() == "dynamic" then
      tilt = math.max(tilt, math.abs(math.deg(p:angle())))
      for _, c in ipairs(p:vertices()) do
        inside = math.min(inside, c[1] - math.min(walls[1], walls[2]), math.max(walls[1], walls[2]) - c[1])
      end
    end
  end
end
scene.on_finish = function(world, ...)
  print(string.format("consolidation_short: piston tilt up to %.4f deg, smallest corner clearance to a side wall %.3f mm",
                      tilt, 1000 * inside))
  assert(tilt < 1e-6, string.format("the guided piston turned by %.3f deg", tilt))
  assert(inside > 0, string.format("a piston corner entered a side wall by %.3f mm", -1000 * inside))
  if finish then return finish(world, ...) end
end
return scene
