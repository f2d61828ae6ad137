// Entry point of the spider12 firmware (PlatformIO env:spider12, CMake strider_firmware_spider12):
// the whole firmware, built for this model (its profile).
#include "control/firmware_profile.h"
using Firmware = strider::FirmwareProfile<strider::robot_index(strider::kSpider12)>;
#include "../firmware_main.h"
