-- bad input: a file name with a NUL byte is refused (C would cut the name there)
local csv = porelab.csv("data.csv\0.txt", { "t" })
