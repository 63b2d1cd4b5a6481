#include "lauxlib.h"
