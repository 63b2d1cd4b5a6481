#include "../core/alloc.h"
/* an include in a comment is no include:
#include "world/world.h"
#include <lua.h> */
// #include <SDL2/SDL.h>
