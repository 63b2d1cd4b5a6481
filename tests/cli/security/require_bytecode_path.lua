-- security: a scene writes a corrupted precompiled chunk into its output folder and points
-- package.path there (this crashed liblua); package.path is not the scene's to change
local code = string.dump(function(t) local x = t.a.b.c; return x .. "abc" .. x end, true)
local f = assert(io.open("evil.lua", "wb"))
f:write(code:sub(1, 35) .. "\255" .. code:sub(37))
f:close()
package.path = porelab.out_dir .. "/?.lua"
local m = require "evil"
print(m({ a = { b = { c = "z" } } }))
