// Entry point of the spider12 firmware (PlatformIO env:spider12, CMake strider_firmware_spider12):
// the whole firmware, compiled for this model and its coxa-femur-tibia legs alone.
#define STRIDER_FIRMWARE_MODEL strider::kSpider12
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kCoxaFemurTibia))
#include "../firmware_main.h"
