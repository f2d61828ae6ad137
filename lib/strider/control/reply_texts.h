//! The controller's reply texts, one array each at namespace scope so that
//! on the AVR they stay in flash (PROGMEM) instead of taking about 600 bytes
//! of the 8 KB RAM; reply.h reads them through FlashText.
#ifndef STRIDER_CONTROL_REPLY_TEXTS_H
#define STRIDER_CONTROL_REPLY_TEXTS_H

#include "reply.h"

namespace strider {
namespace text {

constexpr char kInfoDeadmanStop[] STRIDER_PROGMEM = "info deadman stop";
constexpr char kInfoAvoid_[] STRIDER_PROGMEM = "info avoid ";
constexpr char kCalibrating[] STRIDER_PROGMEM = "calibrating";
constexpr char kOkMove[] STRIDER_PROGMEM = "ok move";
constexpr char kVx[] STRIDER_PROGMEM = "vx";
constexpr char kVy[] STRIDER_PROGMEM = "vy";
constexpr char kWz[] STRIDER_PROGMEM = "wz";
constexpr char kOkStop[] STRIDER_PROGMEM = "ok stop";
constexpr char kOkRelax[] STRIDER_PROGMEM = "ok relax";
constexpr char kOkSpeed[] STRIDER_PROGMEM = "ok speed";
constexpr char kPct[] STRIDER_PROGMEM = "pct";
constexpr char kUnknownGait[] STRIDER_PROGMEM = "unknown gait";
constexpr char kOkGait_[] STRIDER_PROGMEM = "ok gait ";
constexpr char kPoseRefused[] STRIDER_PROGMEM = "pose refused";
constexpr char kOkPose[] STRIDER_PROGMEM = "ok pose";
constexpr char kRoll[] STRIDER_PROGMEM = "roll";
constexpr char kPitch[] STRIDER_PROGMEM = "pitch";
constexpr char kYaw[] STRIDER_PROGMEM = "yaw";
constexpr char kHeightRefused[] STRIDER_PROGMEM = "height refused";
constexpr char kOkHeight[] STRIDER_PROGMEM = "ok height";
constexpr char kMm[] STRIDER_PROGMEM = "mm";
constexpr char kOkAvoid_[] STRIDER_PROGMEM = "ok avoid ";
constexpr char kOn[] STRIDER_PROGMEM = "on";
constexpr char kOff[] STRIDER_PROGMEM = "off";
constexpr char kOkAvoid[] STRIDER_PROGMEM = "ok avoid";
constexpr char kStopMm[] STRIDER_PROGMEM = "stop_mm";
constexpr char kSlowMm[] STRIDER_PROGMEM = "slow_mm";
constexpr char kOkDeadman[] STRIDER_PROGMEM = "ok deadman";
constexpr char kMs[] STRIDER_PROGMEM = "ms";
constexpr char kOkBaud[] STRIDER_PROGMEM = "ok baud";
constexpr char kRate[] STRIDER_PROGMEM = "rate";
constexpr char kSpAfterSaveAndReset[] STRIDER_PROGMEM = " after save and reset";
constexpr char kOkCalStart[] STRIDER_PROGMEM = "ok cal start";
constexpr char kCalStartFirst[] STRIDER_PROGMEM = "cal start first";
constexpr char kOkCalTrim[] STRIDER_PROGMEM = "ok cal trim";
constexpr char kJoint[] STRIDER_PROGMEM = "joint";
constexpr char kDeg[] STRIDER_PROGMEM = "deg";
constexpr char kOkCalOsc[] STRIDER_PROGMEM = "ok cal osc";
constexpr char kOkCalPwm[] STRIDER_PROGMEM = "ok cal pwm";
constexpr char kHz[] STRIDER_PROGMEM = "hz";
constexpr char kOkCal[] STRIDER_PROGMEM = "ok cal";
constexpr char kOsc[] STRIDER_PROGMEM = "osc";
constexpr char kSpTrims[] STRIDER_PROGMEM = " trims=";
constexpr char kStoreFailed[] STRIDER_PROGMEM = "store failed";
constexpr char kOkCalSaved[] STRIDER_PROGMEM = "ok cal saved";
constexpr char kOkCalAborted[] STRIDER_PROGMEM = "ok cal aborted";
constexpr char kOkSaved[] STRIDER_PROGMEM = "ok saved";
constexpr char kOkHelp[] STRIDER_PROGMEM = "ok help walk strafe turn vel stop relax speed gait pose height avoid deadman baud cal save status";
constexpr char kOkLightIgnored[] STRIDER_PROGMEM = "ok light ignored";
constexpr char kOkRc_[] STRIDER_PROGMEM = "ok rc ";
constexpr char kOk[] STRIDER_PROGMEM = "ok";
constexpr char kOkStatus[] STRIDER_PROGMEM = "ok status";
constexpr char kMode[] STRIDER_PROGMEM = "mode";
constexpr char kSpeed[] STRIDER_PROGMEM = "speed";
constexpr char kAvoid[] STRIDER_PROGMEM = "avoid";
constexpr char kFailed[] STRIDER_PROGMEM = "failed";
constexpr char kStale[] STRIDER_PROGMEM = "stale";
constexpr char kNone[] STRIDER_PROGMEM = "none";
constexpr char kSonar[] STRIDER_PROGMEM = "sonar";
constexpr char kDistMm[] STRIDER_PROGMEM = "dist_mm";
constexpr char kDeadmanMs[] STRIDER_PROGMEM = "deadman_ms";
constexpr char kEeprom[] STRIDER_PROGMEM = "eeprom";

}  // namespace text
}  // namespace strider

#endif  // STRIDER_CONTROL_REPLY_TEXTS_H
