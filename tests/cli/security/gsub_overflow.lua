-- errors raised in C carry the scene line: string.gsub calling itself without end
local function f(c) return (string.gsub("a", "a", f)) end
string.gsub("a", "a", f)
