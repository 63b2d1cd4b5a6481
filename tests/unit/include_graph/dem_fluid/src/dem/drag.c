#include "fluid/darcy/darcy.h"
