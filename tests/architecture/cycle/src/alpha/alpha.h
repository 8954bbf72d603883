// Half of a deliberate include cycle between folders: the checker must report it.
#pragma once
#include "beta/beta.h"
