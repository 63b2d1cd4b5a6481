#include "dem/contact.h"
