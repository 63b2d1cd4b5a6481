#include "../core/alloc.h"
#include "mesh/grid.h"
