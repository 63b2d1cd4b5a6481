-- security: an endless loop in the scene file is stopped by the CPU-time budget
local n = 0
while true do n = n + 1 end
