-- ctest soil_simple_shear (short, < 30 s): the cyclic row only, 2 cycles; same criterion as
-- simple_shear_check.lua.
SIMPLE_SHEAR = { rows = "cyclic", cycles = 2 }
return dofile(porelab.scene_dir .. "/simple_shear_check.lua")
