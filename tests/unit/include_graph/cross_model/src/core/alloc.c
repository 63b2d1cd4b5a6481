#include "core/alloc.h"
#include "alloc.h"
#include <stdlib.h>
