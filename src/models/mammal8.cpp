// Entry point of the mammal8 firmware (PlatformIO env:mammal8, CMake strider_firmware_mammal8):
// the whole firmware, built for this model (its profile).
#include "control/firmware_profile.h"
using Firmware = strider::FirmwareProfile<strider::robot_index(strider::kMammal8)>;
#include "../firmware_main.h"
