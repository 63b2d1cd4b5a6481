-- nasty: a world whose metatable is poked
local w = porelab.world {}
local mt = getmetatable(w)
if type(mt) == 'table' then mt.__index = nil; mt.__gc = function() error('gc') end end
return { world = w }
