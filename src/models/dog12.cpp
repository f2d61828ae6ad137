// Entry point of the dog12 firmware (PlatformIO env:dog12, CMake strider_firmware_dog12).
#include "../firmware_model.h"

const strider::RobotModel& firmware_model() { return strider::kDog12; }
