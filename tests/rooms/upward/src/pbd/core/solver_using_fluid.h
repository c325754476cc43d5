#pragma once
// A deliberate error for the test Rooms.AnUpwardIncludeIsRefused: the engine's core may not
// use its fluid.
#include "pbd/fluid/fluid.h"
