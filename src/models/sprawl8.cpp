// Entry point of the sprawl8 firmware (PlatformIO env:sprawl8, CMake strider_firmware_sprawl8).
#include "../firmware_model.h"

const strider::RobotModel& firmware_model() { return strider::kSprawl8; }
