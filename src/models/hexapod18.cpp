// Entry point of the hexapod18 firmware (PlatformIO env:hexapod18, CMake strider_firmware_hexapod18):
// the whole firmware, compiled for this model.
#define STRIDER_FIRMWARE_MODEL strider::kHexapod18
#define STRIDER_WALKER_SOLVERS 1  // one leg solver for its legs of one geometry
#define STRIDER_SERVO_TICK_SLOTS 3  // the servo tick map's ranges shared by the legs' joints
#include "../firmware_main.h"
