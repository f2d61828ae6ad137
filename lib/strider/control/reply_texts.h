//! The controller's and RobotApp's reply and notice texts, at namespace scope
//! so that on the AVR they stay in flash (about 600 bytes of RAM otherwise).
#ifndef STRIDER_CONTROL_REPLY_TEXTS_H
#define STRIDER_CONTROL_REPLY_TEXTS_H

#include "../gait/gait_state.h"
#include "../kinematics/ik_status.h"
#include "battery_monitor.h"
#include "reply.h"

namespace strider {
namespace text {

// Replies with numbers (ReplyWriter::format(): "\1" an integer, "\2" tenths).
constexpr char kOkMoveFmt[] STRIDER_PROGMEM = "ok move vx=" "\2" " vy=" "\2" " wz=" "\2";
constexpr char kOkSpeedFmt[] STRIDER_PROGMEM = "ok speed pct=" "\1";
constexpr char kOkPoseFmt[] STRIDER_PROGMEM = "ok pose roll=" "\2" " pitch=" "\2" " yaw=" "\2";
constexpr char kOkHeightFmt[] STRIDER_PROGMEM = "ok height mm=" "\2";
constexpr char kOkAvoidFmt[] STRIDER_PROGMEM = "ok avoid stop_mm=" "\1" " slow_mm=" "\1";
constexpr char kOkDeadmanFmt[] STRIDER_PROGMEM = "ok deadman ms=" "\1";
constexpr char kOkDeadmanOff[] STRIDER_PROGMEM = "ok deadman off";
constexpr char kOkBaudFmt[] STRIDER_PROGMEM = "ok baud rate=" "\1" " after save and reset";
constexpr char kOkCalTrimFmt[] STRIDER_PROGMEM = "ok cal trim joint=" "\1" " deg=" "\2";
constexpr char kOkCalOscFmt[] STRIDER_PROGMEM = "ok cal osc hz=" "\1";
constexpr char kOkCalPwmFmt[] STRIDER_PROGMEM = "ok cal pwm hz=" "\1";
constexpr char kStatusSpeedFmt[] STRIDER_PROGMEM = " speed=" "\1" " vx=" "\2" " vy=" "\2";
constexpr char kOkCalShowFmt[] STRIDER_PROGMEM = "ok cal osc=" "\1" " trims=";
constexpr char kInfoDeadmanStop[] STRIDER_PROGMEM = "info deadman stop";
constexpr char kInfoAvoid_[] STRIDER_PROGMEM = "info avoid ";
constexpr char kCalibrating[] STRIDER_PROGMEM = "calibrating: cal save or cal abort first";
constexpr char kWz[] STRIDER_PROGMEM = "wz";
constexpr char kOkStop[] STRIDER_PROGMEM = "ok stop";
constexpr char kOkRelax[] STRIDER_PROGMEM = "ok relax";
constexpr char kUnknownGait_[] STRIDER_PROGMEM = "unknown gait: ";
constexpr char kOkGait_[] STRIDER_PROGMEM = "ok gait ";
// err 24 with what the legs reach (motion_reach.h).
constexpr char kPoseRefused_[] STRIDER_PROGMEM = "pose refused: ";
constexpr char kHeightRefused_[] STRIDER_PROGMEM = "height refused: ";
constexpr char kPoseRangesFmt[] STRIDER_PROGMEM = "roll " "\1" ".." "\1" " pitch " "\1";
constexpr char kPoseRanges2Fmt[] STRIDER_PROGMEM = ".." "\1" " yaw " "\1" ".." "\1" " one at a time";
constexpr char kHeightRangeFmt[] STRIDER_PROGMEM = "\1" ".." "\1" " with the body level";
constexpr char kServoFault[] STRIDER_PROGMEM = "servo fault: see pca9685= in status; stop, relax and the rest work";
constexpr char kFallen[] STRIDER_PROGMEM = "fallen: set the robot upright; relax and the rest work";
constexpr char kBatteryCritical[] STRIDER_PROGMEM = "battery critical: charge or swap it; stop, relax and the rest work";
constexpr char kOkAvoid_[] STRIDER_PROGMEM = "ok avoid ";
constexpr char kOkLevel_[] STRIDER_PROGMEM = "ok level ";
constexpr char kNoImu[] STRIDER_PROGMEM = "no imu: level needs an MPU-6050 on the I2C bus (status shows imu=)";
constexpr char kNotStill[] STRIDER_PROGMEM = "not standing still: stop, stand, level off, pose 0 0 0, keep still 1 s";
constexpr char kNotLevel[] STRIDER_PROGMEM = "not level: stand on level ground (within 5 deg)";
constexpr char kOkCalLevelFmt[] STRIDER_PROGMEM = "ok cal level x_mg=" "\1" " y_mg=" "\1" " saved";
constexpr char kLevelMgFmt[] STRIDER_PROGMEM = " level_mg=" "\1" "," "\1";
constexpr char kOn[] STRIDER_PROGMEM = "on";
constexpr char kOff[] STRIDER_PROGMEM = "off";
constexpr char kOkCalStart[] STRIDER_PROGMEM = "ok cal start";
constexpr char kCalStartFirst[] STRIDER_PROGMEM = "cal start first: cal start, then cal trim osc pwm save abort";
constexpr char kStoreFailed[] STRIDER_PROGMEM = "store failed: the EEPROM did not read back; nothing saved";
constexpr char kOkCalSaved[] STRIDER_PROGMEM = "ok cal saved";
constexpr char kOkCalAborted[] STRIDER_PROGMEM = "ok cal aborted";
constexpr char kOkSaved[] STRIDER_PROGMEM = "ok saved";
constexpr char kOkSet_[] STRIDER_PROGMEM = "ok set ";
constexpr char kOkGet[] STRIDER_PROGMEM = "ok get";
constexpr char kOutOfRange_[] STRIDER_PROGMEM = " out of range: ";
constexpr char kNotWithin_[] STRIDER_PROGMEM = " not under the model's own swing: ";
constexpr char kTune[] STRIDER_PROGMEM = "tune";
constexpr char kGaitKey[] STRIDER_PROGMEM = "gait";
// `help`: "ok help " + the command words (error_hints.h) + the model's gaits and heights.
constexpr char kOkHelp_[] STRIDER_PROGMEM = "ok help ";
constexpr char kHelpGaits_[] STRIDER_PROGMEM = "; gaits ";
constexpr char kHelpHeightFmt[] STRIDER_PROGMEM = "; height " "\1" ".." "\1";
constexpr char kOkLightIgnored[] STRIDER_PROGMEM = "ok light ignored";
constexpr char kOkRc_[] STRIDER_PROGMEM = "ok rc ";
constexpr char kOk[] STRIDER_PROGMEM = "ok";
constexpr char kOkStatus[] STRIDER_PROGMEM = "ok status";
constexpr char kMode[] STRIDER_PROGMEM = "mode";
constexpr char kAvoid[] STRIDER_PROGMEM = "avoid";
//! `sonar=` of status, in SonarStatus order (kNoData, kOk, kFailed, kStale).
constexpr char kSonarStatusNames[] STRIDER_PROGMEM = "none\0ok\0failed\0stale";
constexpr char kSonar[] STRIDER_PROGMEM = "sonar";
constexpr char kDistMm[] STRIDER_PROGMEM = "dist_mm";
constexpr char kDeadmanMs[] STRIDER_PROGMEM = "deadman_ms";
constexpr char kEeprom[] STRIDER_PROGMEM = "eeprom";

// RobotApp's notices and status fields.
constexpr char kInfoStrider[] STRIDER_PROGMEM = "info strider ";
constexpr char kReady[] STRIDER_PROGMEM = " ready";
constexpr char kJoints[] STRIDER_PROGMEM = "joints";
constexpr char kBoards[] STRIDER_PROGMEM = "boards";
constexpr char kInfoEeprom[] STRIDER_PROGMEM = "info eeprom ";
constexpr char kDefaults[] STRIDER_PROGMEM = ", defaults";
constexpr char kSlot[] STRIDER_PROGMEM = "slot";
constexpr char kSeq[] STRIDER_PROGMEM = "seq";
constexpr char kOther[] STRIDER_PROGMEM = "other";
constexpr char kVersion[] STRIDER_PROGMEM = "version";
// The start-up configuration's errors (RobotApp::begin()).
constexpr char kErrModel[] STRIDER_PROGMEM = "err 30 model does not fit the firmware: build it for this model";
constexpr char kErrServos[] STRIDER_PROGMEM = "err 37 servos do not fit the firmware: build it for this model";
constexpr char kErrGait[] STRIDER_PROGMEM = "err 38 no gait defaults for the model: add its row to gait_params.h";
constexpr char kState[] STRIDER_PROGMEM = "state";
constexpr char kIk[] STRIDER_PROGMEM = "ik";
constexpr char kServos[] STRIDER_PROGMEM = "servos";
constexpr char kStarting[] STRIDER_PROGMEM = "starting";
constexpr char kLimited[] STRIDER_PROGMEM = "limited";
constexpr char kStackPeak[] STRIDER_PROGMEM = "stack_peak";
constexpr char kPca9685[] STRIDER_PROGMEM = "pca9685";
constexpr char kI2cErrors[] STRIDER_PROGMEM = "i2c_errors";
constexpr char kInfoFaultPca[] STRIDER_PROGMEM = "info fault pca9685 ";
constexpr char kInfoFaultI2c[] STRIDER_PROGMEM = "info fault i2c timeout";
constexpr char kInfoPca[] STRIDER_PROGMEM = "info pca9685 ";
constexpr char kRestored[] STRIDER_PROGMEM = " restored";
constexpr char kNothing[] STRIDER_PROGMEM = "";
constexpr char kInfoHeld[] STRIDER_PROGMEM = "info servos held";
constexpr char kInfoBattery[] STRIDER_PROGMEM = "info battery ";
constexpr char kBatteryMv[] STRIDER_PROGMEM = "battery_mv";
constexpr char kImu[] STRIDER_PROGMEM = "imu";
constexpr char kNone[] STRIDER_PROGMEM = "none";
constexpr char kImuFallen[] STRIDER_PROGMEM = "fallen";
constexpr char kLevel[] STRIDER_PROGMEM = "level";
constexpr char kImuFmt[] STRIDER_PROGMEM = " roll=" "\2" " pitch=" "\2";
constexpr char kInfoFall[] STRIDER_PROGMEM = "info fall";
constexpr char kInfoUpright[] STRIDER_PROGMEM = "info fall cleared";
constexpr char kMv[] STRIDER_PROGMEM = "mv";
constexpr char kWalkFmt[] STRIDER_PROGMEM = " walk_vx=" "\2" " walk_vy=" "\2" " walk_wz=" "\2";
constexpr char kOverrunsFmt[] STRIDER_PROGMEM = " overruns=" "\1" " tick_max_us=" "\1";
constexpr char kBatteryLevelNames[] STRIDER_PROGMEM = "absent\0ok\0low\0critical";
inline FlashText to_flash(BatteryLevel l) { return flash_name(kBatteryLevelNames, 4, uint8_t(l)); }
// The IK's states' names (ik_status.h's to_string()).
constexpr char kIkStatusNames[] STRIDER_PROGMEM = "ok\0clamped\0joint_limit\0unreachable";
inline FlashText to_flash(GaitState s) { return flash_name(kGaitStateNames, kGaitStateCount, uint8_t(s)); }
inline FlashText to_flash(IkStatus s) { return flash_name(kIkStatusNames, 4, uint8_t(s)); }

}  // namespace text
}  // namespace strider

#endif  // STRIDER_CONTROL_REPLY_TEXTS_H
