-- security: a precompiled chunk in the scene's folder is refused by require (text only);
-- bin_helper.lua is a corrupted string.dump that crashed liblua when it was loaded
local helper = require "bin_helper"
return helper
