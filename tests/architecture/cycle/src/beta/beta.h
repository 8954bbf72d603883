// The other half of the deliberate include cycle (alpha/ -> beta/ -> alpha/).
#pragma once
#include "alpha/alpha.h"
