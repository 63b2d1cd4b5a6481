#include "../hydrostatic/hydro.h"
