// The library as every firmware builds it, included first by the file of
// src/models/ (before any other library header): the gait library's
// velocity limits come from the stored table (no IK search built). The model file then names its profile
// (control/firmware_profile.h) and includes firmware_main.h.
#ifndef STRIDER_FIRMWARE_BUILD_H
#define STRIDER_FIRMWARE_BUILD_H

#define STRIDER_VELOCITY_SEARCH 0  // the built-in models have stored velocity limits
#include "control/firmware_profile.h"

#endif  // STRIDER_FIRMWARE_BUILD_H
