-- security: link.csv in the output folder is a dangling symbolic link to a file outside it
local csv = porelab.csv("link.csv", { "t" })
csv:row(1)
csv:close()
