#include "dem/contact.h"
#include "fluid/darcy/darcy.h"
#include "fluid/hydrostatic/hydro.h"
#include "porelab/core.h"
#include <cholmod.h>
