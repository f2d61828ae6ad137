// Entry point of the dog12 firmware (PlatformIO env:dog12, CMake strider_firmware_dog12):
// the whole firmware, built for this model (its profile).
#include "control/firmware_profile.h"
using Firmware = strider::FirmwareProfile<strider::robot_index(strider::kDog12)>;
#include "../firmware_main.h"
