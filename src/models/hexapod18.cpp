// Entry point of the hexapod18 firmware (PlatformIO env:hexapod18, CMake strider_firmware_hexapod18):
// the whole firmware, compiled for this model and its coxa-femur-tibia legs alone.
#define STRIDER_FIRMWARE_MODEL strider::kHexapod18
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kCoxaFemurTibia))
#define STRIDER_WALKER_SOLVERS 1  // one leg solver for its legs of one geometry
#define STRIDER_BODY_SHIFT 0  // its gaits (tripod, ripple, wave) never shift the body
#define STRIDER_GAIT_RELABEL 0  // nor relabel the legs for the direction of travel
#define STRIDER_SERVO_TICK_SLOTS 3  // the servo tick map's ranges shared by the legs' joints
#define STRIDER_SWING_SHAPES (1u << uint8_t(strider::SwingShape::kCycloid))  // its swing shape alone (cycloid)
#define STRIDER_STANCE_DEPTH 0  // no stance depth (its gait defaults)
#include "../firmware_main.h"
