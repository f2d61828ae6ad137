// Entry point of the mammal8 firmware (PlatformIO env:mammal8, CMake strider_firmware_mammal8):
// the whole firmware, compiled for this model and its planar legs alone.
#define STRIDER_FIRMWARE_MODEL strider::kMammal8
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kPlanar))
#include "../firmware_main.h"
