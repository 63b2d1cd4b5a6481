-- security: one huge string from a library function is refused by the memory limit
local s = string.rep("x", 1 << 30)
print(#s)
