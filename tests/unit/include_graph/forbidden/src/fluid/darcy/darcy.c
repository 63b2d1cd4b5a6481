#include "fluid/common/view.h"
#include "darcy.h"
