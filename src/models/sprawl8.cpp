// Entry point of the sprawl8 firmware (PlatformIO env:sprawl8, CMake strider_firmware_sprawl8):
// the whole firmware, compiled for this model.
#include "robots/sprawl8.h"
#define STRIDER_FIRMWARE_MODEL strider::kSprawl8
#include "../firmware_main.h"
