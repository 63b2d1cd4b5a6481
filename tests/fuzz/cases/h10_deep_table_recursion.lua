-- nasty: recursion building nested tables (C stack in table constructors)
local function f(n) return { f(n + 1) } end
f(1)
