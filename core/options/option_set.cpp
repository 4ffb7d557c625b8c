#include "core/options/option_set.h"
