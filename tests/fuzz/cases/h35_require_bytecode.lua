-- nasty: bytecode through require (issue 13 item 1)
-- fuzz-set: long
local f = assert(io.open('out/evil.lua', 'wb'))
local code = string.dump(function() return 1 end)
f:write(code:sub(1, 20) .. string.rep('\255', 200)); f:close()
package.path = 'out/?.lua'
require 'evil'
