-- security: even with package.path set behind the sandbox's back, require looks only in
-- the scene's folder and porelab's library
local code = string.dump(function(t) local x = t.a.b.c; return x .. "abc" .. x end, true)
local f = assert(io.open("evil2.lua", "wb"))
f:write(code:sub(1, 35) .. "\255" .. code:sub(37))
f:close()
rawset(package, "path", porelab.out_dir .. "/?.lua")
local m = require "evil2"
print(m({ a = { b = { c = "z" } } }))
