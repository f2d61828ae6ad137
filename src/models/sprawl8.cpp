// Entry point of the sprawl8 firmware (PlatformIO env:sprawl8, CMake strider_firmware_sprawl8):
// the whole firmware, compiled for this model and its sprawl legs alone.
#define STRIDER_FIRMWARE_MODEL strider::kSprawl8
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kSprawl))
#include "../firmware_main.h"
