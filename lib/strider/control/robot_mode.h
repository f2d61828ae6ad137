//! RobotMode, ControlError and RcLimits: the controller's modes, its reply
//! error codes (20+, after the parser's; docs/protocol.md) and the speeds the
//! RC app's buttons map to.
#ifndef STRIDER_CONTROL_ROBOT_MODE_H
#define STRIDER_CONTROL_ROBOT_MODE_H

#include <stdint.h>

#include "reply.h"

namespace strider {

enum class ControlError : uint8_t {
  kNotCalibrating = 20,  //!< cal trim/osc/pwm/save/abort without `cal start`
  kBusy = 21,            //!< not allowed in this mode (e.g. walking during calibration)
  kStoreFailed = 22,     //!< EEPROM write failed
  kUnknownGait = 23,     //!< the robot has no gait of that name
  kRefused = 24,         //!< pose/height outside what the robot can do
  kTuneRefused = 25,     //!< a live gait parameter outside what the walker allows (the reply gives the range)
  kServoFault = 31,      //!< walking while a servo board does not answer (or is starting again)
  kBatteryCritical = 32, //!< walking on a critically low battery (RobotApp's BatteryMonitor)
  kFallen = 33,          //!< walking while the robot lies tipped over (RobotApp's FallDetector)
  kNoImu = 34,           //!< `level on` without an MPU-6050 (RobotApp: none answered at start-up)
  kNotStill = 35,        //!< `cal level` while the robot walks, lies, sits, levels, or moves during the measurement
  kNotLevel = 36         //!< `cal level`: the accelerometer reads more than 5 deg off level
};

//! What `cal level` found when asked (MotionSink::start_level_cal()).
enum class LevelCalStart : uint8_t {
  kStarted = 0,  //!< measuring: the reply follows in about a second
  kNoImu = 1,    //!< no MPU-6050 (err 34)
  kNotStill = 2  //!< not standing with its servos on, levelling, a body pose, fallen, or measuring already (err 35)
};

enum class RobotMode : uint8_t { kStanding = 0, kWalking = 1, kRelaxed = 2, kCalibrating = 3 };

constexpr char kRobotModeNames[] STRIDER_PROGMEM = "standing\0walking\0relaxed\0calibrating";
inline FlashText to_flash(RobotMode m) { return flash_name(kRobotModeNames, 4, uint8_t(m)); }

//! `err <e> <reason>`.
inline void write_error(ReplyWriter& w, ControlError e, FlashText reason) { write_error(w, uint8_t(e), reason); }

//! Speeds the RC buttons map to at 100 %: seed 000's 155 mm/s and 360 deg in 6 s.
struct RcLimits {
  int32_t linear = 1550;  //!< [0.1 mm/s]
  int32_t turn = 600;     //!< [0.1 deg/s]
  int32_t min_turn = 0;   //!< the slowest turn the pad asks [0.1 deg/s] (0: none)
};

}  // namespace strider

#endif  // STRIDER_CONTROL_ROBOT_MODE_H
