// Entry point of the spider12 firmware (PlatformIO env:spider12, CMake strider_firmware_spider12):
// the whole firmware, built for this model (its profile).
#include "../firmware_build.h"
using Firmware = strider::FirmwareProfile<strider::robot_index(strider::kSpider12)>;
#include "../firmware_main.h"
