// Entry point of the hexapod18 firmware (PlatformIO env:hexapod18, CMake strider_firmware_hexapod18):
// the whole firmware, compiled for this model.
#include "robots/hexapod18.h"
#define STRIDER_FIRMWARE_MODEL strider::kHexapod18
#include "../firmware_main.h"
