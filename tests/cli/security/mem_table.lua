-- security: many small objects are stopped by the memory limit too
local t = {}
local i = 0
while true do
  i = i + 1
  t[i] = { i }
end
