-- sandbox: writing outside the output folder is refused
local f = io.open("/tmp/porelab-sandbox-escape.txt", "w")
