// Entry point of the mammal8 firmware (PlatformIO env:mammal8, CMake strider_firmware_mammal8):
// the whole firmware, compiled for this model and four legs of walking state.
#define STRIDER_FIRMWARE_MODEL strider::kMammal8
#define STRIDER_WALKER_LEGS 4  // walking state for four legs, not six
#define STRIDER_WALKER_SOLVERS 1  // one leg solver for its legs of one geometry
#define STRIDER_SERVO_TICK_SLOTS 2  // the servo tick map's ranges shared by the legs' joints
#include "../firmware_main.h"
