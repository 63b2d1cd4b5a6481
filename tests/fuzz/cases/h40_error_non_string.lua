-- nasty: error objects that are not strings, with escapes
error(setmetatable({}, { __tostring = function() return '\27[31mred' end }))
