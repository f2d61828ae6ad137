// Entry point of the sprawl8 firmware (PlatformIO env:sprawl8, CMake strider_firmware_sprawl8):
// the whole firmware, built for this model (its profile).
#include "control/firmware_profile.h"
using Firmware = strider::FirmwareProfile<strider::robot_index(strider::kSprawl8)>;
#include "../firmware_main.h"
