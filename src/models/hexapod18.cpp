// Entry point of the hexapod18 firmware (PlatformIO env:hexapod18, CMake strider_firmware_hexapod18).
#include "../firmware_model.h"

const strider::RobotModel& firmware_model() { return strider::kHexapod18; }
