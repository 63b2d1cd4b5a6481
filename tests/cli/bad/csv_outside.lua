-- sandbox: porelab.csv writes only inside the output folder
local csv = porelab.csv("../escape.csv", { "t" })
