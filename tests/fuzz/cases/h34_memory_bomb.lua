-- nasty: string doubling (issue 13 item 5: no memory limit yet)
-- fuzz-set: long
local s = 'x'
while true do s = s .. s end
