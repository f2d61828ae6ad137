// The robot this firmware drives: defined once per build by one file of
// src/models/ (PlatformIO picks it with build_src_filter, CMake per target),
// so the firmware itself needs no #define configuration.
#ifndef STRIDER_FIRMWARE_MODEL_H
#define STRIDER_FIRMWARE_MODEL_H

#include "robots/all_robots.h"

const strider::RobotModel& firmware_model();

#endif
