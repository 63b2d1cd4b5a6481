-- nasty: writing outside the output folder
local f = io.open('../escape.txt', 'w')
if f then f:write('x') f:close() end
local g = io.open('/tmp/porelab-fuzz-escape', 'w')
if g then g:write('x') g:close() end
