// Entry point of the sprawl8 firmware (PlatformIO env:sprawl8, CMake strider_firmware_sprawl8):
// the whole firmware, compiled for this model and four legs of walking state.
#define STRIDER_FIRMWARE_MODEL strider::kSprawl8
#define STRIDER_WALKER_LEGS 4  // walking state for four legs, not six
#include "../firmware_main.h"
