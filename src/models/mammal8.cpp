// Entry point of the mammal8 firmware (PlatformIO env:mammal8, CMake strider_firmware_mammal8).
#include "../firmware_model.h"

const strider::RobotModel& firmware_model() { return strider::kMammal8; }
