#include "geom/clip.h"
#  include "core/alloc.h"
