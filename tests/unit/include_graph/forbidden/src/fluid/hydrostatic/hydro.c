#include "../common/view.h"
