-- security: a module name cannot climb out of the scene's folder
require "..passwd"
