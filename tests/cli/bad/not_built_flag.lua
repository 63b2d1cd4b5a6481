-- bad input: a MIMES flag whose feature porelab does not build
local w = porelab.world { flags = { EXODUSFLAG = 1 } }
return w
