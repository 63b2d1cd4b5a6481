-- sandbox: reading outside the scene's folder is refused
local f = io.open("../../../CMakeLists.txt", "r")
