-- nasty: string doubling (issue 13 item 5: no memory limit yet)
-- fuzz-set: long
-- fuzz-expect: fail (issue 13 item 5: no memory limit; stopped by ulimit -v without a line)
local s = 'x'
while true do s = s .. s end
