-- security: an endless loop in a __gc finalizer could not be stopped (Lua runs finalizers
-- with hooks off), so finalizers are refused in the sandbox
setmetatable({}, { __gc = function() while true do end end })
