-- An imperative script that writes about 40 KB into log.csv and never closes it: a failed
-- write when the program closes the file must exit non-zero, not "ran to completion".
local w = porelab.world { gravity = { 0, -10 }, dt = 1e-3 }
local m = w:material { name = "sand", density = 2650, kn = 1e6 }
w:disc { center = { 0, 0.2 }, radius = 0.1, material = m }
local log = porelab.csv("log.csv", { "t", "i", "note" })
for i = 1, 1000 do
  log:row(w:time(), i, "forty bytes of text in every row")
end
