-- sandbox: precompiled (binary) chunks are refused
local f = load(string.dump(function() return 1 end))
