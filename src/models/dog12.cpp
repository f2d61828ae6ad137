// Entry point of the dog12 firmware (PlatformIO env:dog12, CMake strider_firmware_dog12):
// the whole firmware, compiled for this model and four legs of walking state.
#define STRIDER_FIRMWARE_MODEL strider::kDog12
#define STRIDER_WALKER_LEGS 4  // walking state for four legs, not six
#define STRIDER_WALKER_SOLVERS 2  // two leg solvers (left and right legs)
#include "../firmware_main.h"
