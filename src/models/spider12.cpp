// Entry point of the spider12 firmware (PlatformIO env:spider12, CMake strider_firmware_spider12):
// the whole firmware, compiled for this model, its coxa-femur-tibia legs alone and four legs of walking state.
#define STRIDER_FIRMWARE_MODEL strider::kSpider12
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kCoxaFemurTibia))
#define STRIDER_WALKER_LEGS 4  // walking state for four legs, not six
#include "../firmware_main.h"
