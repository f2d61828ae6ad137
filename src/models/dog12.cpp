// Entry point of the dog12 firmware (PlatformIO env:dog12, CMake strider_firmware_dog12):
// the whole firmware, compiled for this model and its abduction legs alone.
#define STRIDER_FIRMWARE_MODEL strider::kDog12
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kAbduction))
#include "../firmware_main.h"
