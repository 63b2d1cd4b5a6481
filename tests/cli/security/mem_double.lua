-- security: string doubling is stopped by the memory limit (it reached 3 GB in 4 s)
local s = "x"
while true do
  s = s .. s
end
