-- security: link.txt in the output folder is a dangling symbolic link to a file outside
-- it; writing through it is refused
local f = io.open("link.txt", "w")
f:write("escaped\n")
f:close()
