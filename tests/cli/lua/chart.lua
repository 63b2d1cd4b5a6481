-- porelab.chart: a falling disc against y0 - g t^2/2 (tests/cli/tests.cmake: cli_scene_chart)
local w = porelab.world { gravity = {0, -9.81} }
local m = w:material { name = "sand", density = 2650, kn = 1e6, friction = 0.5, restitution = 0.3 }
w:wall { from = {0, 0}, to = {1, 0}, material = m }
local d = w:disc { center = {0.5, 0.5}, radius = 0.05, material = m }
local t, y, ya = {}, {}, {}
w:step(1)
for k = 1, 40 do
  w:run_until(0.01 * k)
  t[#t + 1] = w:time()
  local _, py = d:position(); y[#y + 1] = py
  ya[#ya + 1] = 0.5 - 0.5 * 9.81 * w:time()^2
end
local p = porelab.chart { file = "fall.png", title = "A falling disc", xlabel = "time (s)",
  ylabel = "height (m)", series = {
    { name = "porelab", x = t, y = y, style = "points" },
    { name = "y0 - g t^2/2", x = t, y = ya, style = "dashed", color = "#444444" } } }
print("chart", p)
