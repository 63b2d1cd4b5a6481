-- ctest soil_simple_shear (short, < 30 s): the cyclic row only, 3 cycles (the dry
-- constant-volume sample needs three to lose more than 0.1 sigma'_v0); same criterion as
-- simple_shear_check.lua.
SIMPLE_SHEAR = { rows = "cyclic", cycles = 3 }
return dofile(porelab.scene_dir .. "/simple_shear_check.lua")
