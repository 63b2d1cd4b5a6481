-- security: catching the CPU-time error with pcall does not keep the scene running
local w = porelab.world { dt = 1e-3 }
while true do
  pcall(function() while true do w:time() end end)
end
