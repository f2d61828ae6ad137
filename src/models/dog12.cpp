// Entry point of the dog12 firmware (PlatformIO env:dog12, CMake strider_firmware_dog12):
// the whole firmware, compiled for this model, its abduction legs alone and four legs of walking state.
#define STRIDER_FIRMWARE_MODEL strider::kDog12
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kAbduction))
#define STRIDER_WALKER_LEGS 4  // walking state for four legs, not six
#define STRIDER_WALKER_SOLVERS 2  // two leg solvers (left and right legs)
#define STRIDER_SWING_SHAPES (1u << uint8_t(strider::SwingShape::kRectangle))  // its swing shape alone (rectangle)
#define STRIDER_STANCE_DEPTH 0  // no stance depth (its gait defaults)
#include "../firmware_main.h"
