-- bad input: a Lua syntax error
local w = porelab.world {}
local m = w:material { name = "sand" density = 2650 }
return w
