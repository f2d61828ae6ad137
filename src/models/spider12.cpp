// Entry point of the spider12 firmware (PlatformIO env:spider12, CMake strider_firmware_spider12).
#include "../firmware_model.h"

const strider::RobotModel& firmware_model() { return strider::kSpider12; }
