//! RobotSensing: what RobotApp senses besides the link and what it does to
//! the robot: the battery's level, the IMU's attitude, the fall it sees, the
//! level body (`level on`) and the `cal level` measurement (docs/imu.md).
#ifndef STRIDER_CONTROL_ROBOT_SENSING_H
#define STRIDER_CONTROL_ROBOT_SENSING_H

#include <stdint.h>

#include "../sensing/attitude_filter.h"
#include "../sensing/level_calibration.h"
#include "battery_monitor.h"
#include "control_tick.h"
#include "fall_detector.h"
#include "level_body.h"
#include "link_ports.h"
#include "reply_texts.h"
#include "robot_mode.h"
#include "settings.h"
#include "walker_motion.h"
#include "yaw_hold.h"

namespace strider {

static_assert(kLevelTickS * 1e6 == double(kTickPeriodUs), "level_body.h's tick is RobotApp's");

template <typename S, typename P = HostProfile<S>>
class RobotSensing {
 public:
  //! Whether an MPU-6050 answered at start-up (never called: no `imu=`);
  //! with one, the gyro's offset is learnt fast until the robot first stands.
  void set_imu_present(bool present) {
    imu_probed_ = true, imu_present_ = present;
    if (!present) return;
    attitude_.set_gains(LevelBody<S>::learning_gains(attitude_.gains(), true));
    level_.start_learning();
  }

  //! The battery divider's ADC reading, once a tick: a new level is a
  //! notice; a critical pack sits the robot down and refuses walking (err 32).
  template <typename Ctl, typename Link>
  STRIDER_NOINLINE void battery_reading(uint16_t adc_code, Ctl& ctl, WalkerMotion<S, P>& motion, Link& link) {
    if (!battery.add(adc_code)) return;
    ReplyLine line;
    line.w.text(FlashText{text::kInfoBattery}).text(text::to_flash(battery.level()));
    line.w.field(FlashText{text::kMv}, battery.mv());
    link.send_line(kAllPorts, line.buf);
    ctl.set_battery_critical(battery.critical());
    if (battery.critical()) motion.walker().engine().sit_down();
  }

  //! One IMU sample per tick (nullptr: failed read) into `cal level`, the
  //! attitude, the level body and the fall (`info fall`, err 33).
  template <typename Ctl, typename Ports, typename Link>
  void imu_sample(const ImuSample<S>* sample, Ctl& ctl, WalkerMotion<S, P>& motion, bool servos_on, Ports& ports,
                  Link& link) {
    if (level_cal_.running() && imu_present_) level_cal_sample(sample, motion, servos_on, ctl, ports, link);
    if (!update(sample, ctl.settings(), motion, servos_on)) return;
    send_notice(FlashText{fall_.fallen() ? text::kInfoFall : text::kInfoUpright}, link);
    ctl.set_fallen(fall_.fallen());
  }
  bool fallen() const { return fall_.fallen(); }

  //! `level on|off`; false without an IMU. Off levels the body to the feet.
  bool set_level(bool on, WalkerMotion<S, P>& motion) {
    if (!imu_present_) return false;
    level_.set_enabled(on);
    if (!on) motion.set_body_tilt(S(0), S(0));
    return true;
  }

  //! `cal level`: starts when standing still, servos on, level off, no pose.
  LevelCalStart start_level_cal(const WalkerMotion<S, P>& motion, bool servos_on) {
    if (!imu_present_) return LevelCalStart::kNoImu;
    if (level_cal_.running() || !attitude_.has_attitude() || fall_.fallen() || !servos_on || level_.enabled() ||
        level_.learning() || motion.walker().engine().state() != GaitState::kStanding ||
        motion.offsets().roll_rad != S(0) || motion.offsets().pitch_rad != S(0))
      return LevelCalStart::kNotStill;
    level_cal_.start();  // again with the reply's port (LinkPorts::reply_line())
    return LevelCalStart::kStarted;
  }
  LevelCalibration<S>& level_cal() { return level_cal_; }
  //! ` battery_mv=` while a pack is seen, ` imu=` with roll and pitch [deg].
  void write_status(ReplyWriter& w) const {
    if (battery.present()) w.field(FlashText{text::kBatteryMv}, battery.mv());
    if (!imu_probed_) return;
    w.field_text(FlashText{text::kImu}, !imu_present_ ? FlashText{text::kNone}
                                        : fall_.fallen() ? FlashText{text::kImuFallen}
                                        : level_.enabled() ? FlashText{text::kLevel} : FlashText{text::kOk});
    constexpr S kDeg = scalar<S>(57.29577951308232);
    if (imu_present_ && attitude_.has_attitude())
      w.format(FlashText{text::kImuFmt}, to_tenths(attitude_.roll_rad() * kDeg), to_tenths(attitude_.pitch_rad() * kDeg));
  }

  BatteryMonitor battery;
  const AttitudeFilter<S>& attitude() const { return attitude_; }
  const LevelBody<S>& level() const { return level_; }
  const YawHold<S>& yaw_hold() const { return yaw_; }

 private:
  //! One raw sample into `cal level`; leaving the stand or a failed read ends
  //! it. Done: the attitude afresh from the corrected accelerometer, the
  //! gyro's bias kept (else the step takes the filter's 2 s and overshoots).
  template <typename Ctl, typename Ports, typename Link>
  STRIDER_NOINLINE void level_cal_sample(const ImuSample<S>* sample, const WalkerMotion<S, P>& motion, bool servos_on,
                                         Ctl& ctl, Ports& ports, Link& link) {
    int8_t x = 0, y = 0;
    const LevelCalStatus st = sample == nullptr ? (level_cal_.stop(), LevelCalStatus::kNoReading)
                              : motion.walker().engine().state() != GaitState::kStanding || !servos_on
                                  ? (level_cal_.stop(), LevelCalStatus::kMoving)
                                  : level_cal_.add(*sample, attitude_.gyro_bias_rad_s(), &x, &y);
    if (st == LevelCalStatus::kCollecting) return;
    if (st == LevelCalStatus::kDone) {
      const Vec3<S> bias = attitude_.gyro_bias_rad_s();
      attitude_.reset();
      attitude_.set_gyro_bias(bias);
    }
    ports.level_cal_reply(st, x, y, level_cal_.tag(), ctl, link);
  }

  //! True when fallen() changed.
  bool update(const ImuSample<S>* sample, const Settings& settings, WalkerMotion<S, P>& motion, bool servos_on) {
    if (sample == nullptr || !imu_present_) return false;
    ImuSample<S> s = *sample;
    constexpr S kMs2PerMg = scalar<S>(kStandardGravity / 1000.0);
    s.accel_m_s2.x -= S(int(settings.accel_x_mg)) * kMs2PerMg;
    s.accel_m_s2.y -= S(int(settings.accel_y_mg)) * kMs2PerMg;
    attitude_.update(s, scalar<S>(double(kTickPeriodUs) * 1e-6));
    hold_yaw(s.gyro_rad_s, motion, servos_on);
    if (!attitude_.has_attitude()) return false;
    level_body(motion, servos_on);
    return fall_.update(attitude_.tilt_rad());
  }
  //! The heading hold (yaw_hold.h): held upright on the feet walking a
  //! command without a turn (also stopping or standing: a trim may bring
  //! the gait's command to zero), the offset learnt standing still with
  //! none. Turns stay open loop: mammal8's turn on the ground swings between
  //! 1 and 5 deg/s at one gait rate, and held it made 2.8 of 3.5 deg/s
  //! where open loop it makes 3.7 (docs/imu.md).
  void hold_yaw(const Vec3<S>& gyro_rad_s, WalkerMotion<S, P>& motion, bool servos_on) {
    const Twist& c = motion.command();
    const bool none = c.vx == 0 && c.vy == 0 && c.wz == 0;
    const GaitState st = motion.walker().engine().state();
    const bool on_feet = st == GaitState::kWalking || st == GaitState::kStopping || st == GaitState::kStanding;
    const bool upright = servos_on && !fall_.fallen();
    const S gyro_y = gyro_rad_s.y - attitude_.gyro_bias_rad_s().y;
    if (yaw_.step(gyro_y, gyro_rad_s.z, attitude_.roll_rad(), attitude_.pitch_rad(), c.wz, upright && !none && c.wz == 0 && on_feet,
                  upright && none && st == GaitState::kStanding, motion.walker().engine().step_hz(),
                  scalar<S>(double(kTickPeriodUs) * 1e-6)))
      motion.set_yaw_trim(yaw_.trim_tenths());
  }

  //! Learning ends at the first stand; the level acts standing or walking.
  void level_body(WalkerMotion<S, P>& motion, bool servos_on) {
    const GaitState st = motion.walker().engine().state();
    if (level_.learning() && st == GaitState::kStanding) {
      level_.stop_learning();
      attitude_.set_gains(LevelBody<S>::learning_gains(attitude_.gains(), false));
    }
    if (fall_.fallen() || !servos_on || st == GaitState::kSitting || st == GaitState::kStandingUp ||
        st == GaitState::kSittingDown)
      return;
    S roll = motion.offsets().roll_rad, pitch = motion.offsets().pitch_rad;
    if (level_.step(attitude_.roll_rad(), attitude_.pitch_rad(), &roll, &pitch)) motion.set_body_tilt(roll, pitch);
  }

  AttitudeFilter<S> attitude_;
  FallDetector<S> fall_;
  LevelBody<S> level_;
  LevelCalibration<S> level_cal_;
  YawHold<S> yaw_;
  bool imu_probed_ = false;
  bool imu_present_ = false;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_ROBOT_SENSING_H
