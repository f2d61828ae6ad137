// Entry point of the hexapod18 firmware (PlatformIO env:hexapod18, CMake strider_firmware_hexapod18):
// the whole firmware, compiled for this model and its coxa-femur-tibia legs alone.
#define STRIDER_FIRMWARE_MODEL strider::kHexapod18
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kCoxaFemurTibia))
#include "../firmware_main.h"
