// Entry point of the spider12 firmware (PlatformIO env:spider12, CMake strider_firmware_spider12):
// the whole firmware, compiled for this model.
#include "robots/spider12.h"
#define STRIDER_FIRMWARE_MODEL strider::kSpider12
#include "../firmware_main.h"
