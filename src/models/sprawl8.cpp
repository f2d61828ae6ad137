// Entry point of the sprawl8 firmware (PlatformIO env:sprawl8, CMake strider_firmware_sprawl8):
// the whole firmware, compiled for this model, its sprawl legs alone and four legs of walking state.
#define STRIDER_FIRMWARE_MODEL strider::kSprawl8
#define STRIDER_LEG_KINDS (1u << uint8_t(strider::LegKind::kSprawl))
#define STRIDER_WALKER_LEGS 4  // walking state for four legs, not six
#define STRIDER_SWING_SHAPES (1u << uint8_t(strider::SwingShape::kEllipse))  // its swing shape alone (ellipse)
#define STRIDER_STANCE_DEPTH 0  // no stance depth (its gait defaults)
#include "../firmware_main.h"
