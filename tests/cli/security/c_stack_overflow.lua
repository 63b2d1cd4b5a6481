-- errors raised in C carry the scene line: a __tostring that calls tostring on itself
-- overflows the C stack
local t = setmetatable({}, { __tostring = function(x) return tostring(x) end })
local s = tostring(t)
