-- nasty: recursion through a C function (C stack overflow)
local function f(s) return (string.gsub(s, '.', f)) end
f('abc')
