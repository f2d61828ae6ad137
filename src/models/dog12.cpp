// Entry point of the dog12 firmware (PlatformIO env:dog12, CMake strider_firmware_dog12):
// the whole firmware, compiled for this model.
#include "robots/dog12.h"
#define STRIDER_FIRMWARE_MODEL strider::kDog12
#include "../firmware_main.h"
