#include "porelab/core.h"
