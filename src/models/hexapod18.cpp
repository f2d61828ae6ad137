// Entry point of the hexapod18 firmware (PlatformIO env:hexapod18, CMake strider_firmware_hexapod18):
// the whole firmware, built for this model (its profile).
#include "control/firmware_profile.h"
using Firmware = strider::FirmwareProfile<strider::robot_index(strider::kHexapod18)>;
#include "../firmware_main.h"
