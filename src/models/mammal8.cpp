// Entry point of the mammal8 firmware (PlatformIO env:mammal8, CMake strider_firmware_mammal8):
// the whole firmware, compiled for this model.
#include "robots/mammal8.h"
#define STRIDER_FIRMWARE_MODEL strider::kMammal8
#include "../firmware_main.h"
