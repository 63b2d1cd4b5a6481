-- errors raised inside an embedded helper also name the scene line that called it
local mimes = require "porelab.mimes"
local M = mimes.session()
M.scene(5)
