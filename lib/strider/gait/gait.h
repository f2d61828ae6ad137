//! The gait module in one include: gait tables and library, per-model gait
//! defaults, the engine, moves and the walker (docs/gaits.md).
#ifndef STRIDER_GAIT_GAIT_H
#define STRIDER_GAIT_GAIT_H

#include "gait_library.h"
#include "gait_params.h"
#include "move.h"
#include "walker.h"

#endif  // STRIDER_GAIT_GAIT_H
