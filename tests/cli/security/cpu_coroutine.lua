-- security: an endless loop inside a coroutine is stopped too
local co = coroutine.wrap(function() while true do end end)
co()
