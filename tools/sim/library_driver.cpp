// LibraryDriver: the firmware's own control chain, compiled for the host:
// Bluetooth bytes -> strider::RobotApp (parser, controller, walker, servo
// stage) -> ServoOutput calls -> PCA9685 registers -> pulse widths.
#include <cmath>
#include <cstdio>
#include <deque>

#include "driver.h"
#include "host_robot.h"

namespace strider_sim {

namespace {

constexpr uint8_t kBluetoothPort = 1;
constexpr double kBaud = 9600;                     // HC-05 default
constexpr double kByteUs = 10.0 * 1e6 / kBaud;     // start + 8 data + stop bits
constexpr double kNoEchoUs = 38000;                // HC-SR04's "nothing in range" pulse
constexpr double kUsPerMmRoundTrip = 2.0 / 0.343;  // sound at 343 m/s, out and back

struct Lines {
  std::vector<std::string>* out;
  void send_line(uint8_t /*port*/, const char* line) { out->push_back(line); }
};

class LibraryDriver : public Driver, private HostParts {
 public:
  LibraryDriver(const strider::RobotModel& model, double osc_hz, RangeFn range, const GaitOverrides& gait)
      : app_(model, boards, store), model_(model), gait_(gait), osc_hz_(osc_hz), range_(std::move(range)) {}

  const char* mode() const override { return "library"; }

  bool begin(std::string* error) override {
    Lines link{&lines_};
    if (!app_.begin(0, link)) {
      *error = lines_.empty() ? "robot did not start" : lines_.back();
      return false;
    }
    params_ = *strider::gait_params_for(model_);
    const bool params_changed = gait_.step_height_mm > 0 || gait_.step_length_mm > 0 || gait_.cycle_s > 0 || !gait_.swing.empty();
    if (params_changed && !apply_gait_overrides(error)) return false;
    apply_duty();
    update_pulses();
    return true;
  }

  void send(const std::string& bytes, uint64_t at_us) override {
    double t = std::max(double(at_us), next_byte_us_);
    for (char c : bytes) {
      rx_.push_back({uint64_t(t), uint8_t(c)});
      t += kByteUs;
    }
    next_byte_us_ = t;
  }

  void advance_to(uint64_t now_us) override {
    Lines link{&lines_};
    for (;;) {
      const uint64_t byte_at = rx_.empty() ? UINT64_MAX : rx_.front().at_us;
      const uint64_t next = std::min(byte_at, next_tick_us_);
      if (next > now_us) break;
      if (byte_at <= next_tick_us_) {
        app_.on_byte(kBluetoothPort, rx_.front().byte, uint32_t(byte_at), link);
        rx_.pop_front();
        apply_duty();  // the byte may have ended a `gait NAME` line
        continue;
      }
      tick(next_tick_us_, link);
      next_tick_us_ += strider::kTickPeriodUs;
    }
  }

  const ChannelPulse* pulses() const override { return pulses_; }

  std::vector<std::string> take_lines() override {
    std::vector<std::string> out;
    out.swap(lines_);
    return out;
  }

  bool odometry(double* x_mm, double* y_mm, double* yaw_rad) const override {
    const auto& e = app_.motion().walker().engine();
    *x_mm = double(e.odometry_x());
    *y_mm = double(e.odometry_y());
    *yaw_rad = double(e.odometry_yaw());
    return true;
  }

  bool gait_info(GaitInfo* info) const override {
    const auto& motion = app_.motion();
    info->gait = motion.gait().name;
    info->duty = double(motion.gait().duty);
    info->swing = strider::to_string(params_.shape);
    info->step_height_mm = double(params_.step_height_mm);
    info->step_length_mm = double(params_.step_length_mm);
    info->cycle_s = double(params_.cycle_s);
    info->body_height_mm = double(motion.stand_height_mm() + motion.offsets().translation_mm.z);
    const strider::GaitTable& g = motion.gait();
    info->leg_count = g.leg_count;
    info->offsets.assign(g.offset, g.offset + g.leg_count);
    info->shift_body = g.shift_body;
    info->relabel_by_direction = g.relabel_by_direction;
    info->default_gait = params_.default_gait;
    info->stance_depth_mm = double(params_.stance_depth_mm);
    info->foot_radius_mm = double(params_.foot_radius_mm);
    info->com_x_mm = double(params_.com_x_mm);
    info->com_y_mm = double(params_.com_y_mm);
    info->margin_mm = double(params_.margin_mm);
    info->shift_budget_mm = double(params_.shift_budget_mm);
    info->sit_drop_mm = double(params_.sit_drop_mm);
    const strider::TuneBounds b = app_.tune_bounds();
    info->has_bounds = true;
    const strider::TuneRange* r[4] = {&b.step_height, &b.step_length, &b.cycle, &b.duty};
    double* out[4] = {info->step_height_range, info->step_length_range, info->cycle_range, info->duty_range};
    for (int k = 0; k < 4; ++k) out[k][0] = r[k]->lo / 100.0, out[k][1] = r[k]->hi / 100.0;
    // The duty's range at any cycle (the robot's is the part the cycle set
    // leaves the servos: 1 - lift / cycle; the tuner keeps to it).
    strider::GaitTable own;
    if (strider::load_gait(motion.walker().leg_count(), motion.gait().name, &own)) {
      const strider::TuneRange d = strider::duty_range(own);
      info->duty_range[0] = d.lo / 100.0, info->duty_range[1] = d.hi / 100.0;
    }
    info->swing_lift_ms = double(motion.walker().engine().config().limits.lift_ms);
    for (uint8_t k = 0; k < strider::kSwingShapeCount; ++k)
      if ((b.shapes >> k) & 1) info->swings.push_back(strider::to_string(strider::SwingShape(k)));
    info->transition_s = double(params_.transition_s);
    return true;
  }

 private:
  struct Rx {
    uint64_t at_us;
    uint8_t byte;
  };

  void tick(uint64_t t_us, Lines& link) {
    const uint32_t now = uint32_t(t_us);
    // The echo of the last ping is measured by the time its pulse ends.
    if (echo_pending_ && double(t_us) >= echo_at_us_) {
      strider::EchoSample s{strider::EchoKind::kEcho, uint16_t(echo_width_us_), uint32_t(ping_us_)};
      app_.sonar().add(s, now);
      echo_pending_ = false;
    }
    if (!echo_pending_ && app_.sonar().ping_due(now)) {
      const double d = range_ ? range_() : -1.0;
      echo_width_us_ = d < 0 ? kNoEchoUs : d * kUsPerMmRoundTrip;
      ping_us_ = t_us;
      echo_at_us_ = double(t_us) + echo_width_us_;
      echo_pending_ = true;
    }
    feed_sensors(link);
    app_.tick(now, link);
    update_pulses();
  }

  // The robot's own sensors, as the firmware reads them before its tick: the
  // MPU-6050 (when fitted) and the battery divider's pin through a 10-bit ADC
  // against 5 V.
  // The IMU: the mean of the readings since the last tick. The firmware's
  // part filters at 5 Hz; one raw reading a tick, at the same point of every
  // tick, would see the same part of each servo frame's jerk (docs/imu.md).
  void feed_sensors(Lines& link) {
    const SensorInputs& in = sensors();
    if (in.imu_fitted) {
      if (!imu_announced_) app_.set_imu_present(true);
      imu_announced_ = true;
      const ImuReading& r = imu_n_ > 0 ? imu_sum_ : in.imu;
      const double k = imu_n_ > 0 ? 1.0 / imu_n_ : 1.0;
      strider::ImuSample<float> s;
      s.accel_m_s2 = strider::Vec3<float>(float(r.accel_m_s2.x * k), float(r.accel_m_s2.y * k), float(r.accel_m_s2.z * k));
      s.gyro_rad_s = strider::Vec3<float>(float(r.gyro_rad_s.x * k), float(r.gyro_rad_s.y * k), float(r.gyro_rad_s.z * k));
      s.temp_c = float(in.imu.temp_c);
      imu_sum_ = ImuReading();
      imu_n_ = 0;
      app_.imu(&s, link);
    }
    const double code = std::floor(in.battery_pin_v * 1024.0 / 5.0);
    app_.battery(uint16_t(code < 0 ? 0 : code > 1023 ? 1023 : code), link);
  }

  void update_pulses() { boards.pulses(osc_hz_, pulses_); }

 public:
  void set_sensors(const SensorInputs& s) override {
    Driver::set_sensors(s);
    if (!s.imu_fitted) return;
    Vec& a = imu_sum_.accel_m_s2;
    Vec& w = imu_sum_.gyro_rad_s;
    a = Vec{a.x + s.imu.accel_m_s2.x, a.y + s.imu.accel_m_s2.y, a.z + s.imu.accel_m_s2.z};
    w = Vec{w.x + s.imu.gyro_rad_s.x, w.y + s.imu.gyro_rad_s.y, w.z + s.imu.gyro_rad_s.z};
    ++imu_n_;
  }

 private:

  // The duty override on the gait walked now, when it does not have it yet
  // and keeps its support with it (gait_library.h's checks of the built-in
  // tables); refused once per gait, in the robot's log.
  void apply_duty() {
    if (!(gait_.duty > 0)) return;
    auto& engine = app_.motion().walker().engine();
    strider::GaitTable g = engine.gait();
    if (g.duty == float(gait_.duty) || refused_duty_gait_ == g.name) return;
    g.duty = float(gait_.duty);
    const uint8_t min_support = g.leg_count == 4 ? 2 : 3;
    if (!strider::gait_table::valid(g) || !strider::gait_table::keeps_support(g, min_support) ||
        (g.shift_body && !strider::gait_table::swings_separated(g))) {
      refused_duty_gait_ = g.name;
      char line[96];
      std::snprintf(line, sizeof line, "sim duty %.3f refused for gait %s: it keeps its %.3f", gait_.duty, g.name,
                    double(engine.gait().duty));
      lines_.push_back(line);
      return;
    }
    engine.set_gait(g);
  }

  // The model's gait defaults with the overrides in; the robot is still
  // sitting, as at power-up, when the walker takes them.
  bool apply_gait_overrides(std::string* error) {
    strider::GaitParams p = params_;
    if (gait_.step_height_mm > 0) p.step_height_mm = float(gait_.step_height_mm);
    if (gait_.step_length_mm > 0) p.step_length_mm = float(gait_.step_length_mm);
    if (gait_.cycle_s > 0) p.cycle_s = float(gait_.cycle_s);
    if (!gait_.swing.empty() && !strider::parse_swing_shape(gait_.swing.c_str(), p.shape)) {
      *error = "unknown swing shape " + gait_.swing;
      return false;
    }
    if (!app_.set_gait_params(p)) {
      *error = "the walker refused the gait parameters (a step the legs cannot reach, or a swing shape not built in)";
      return false;
    }
    params_ = p;
    return true;
  }

  HostApp app_;
  bool imu_announced_ = false;
  ImuReading imu_sum_;  // the readings since the last tick, summed (feed_sensors())
  int imu_n_ = 0;
  const strider::RobotModel& model_;
  GaitOverrides gait_;
  strider::GaitParams params_{};  // the gait parameters walked: the defaults with the overrides
  std::string refused_duty_gait_;
  double osc_hz_;
  RangeFn range_;
  std::deque<Rx> rx_;
  double next_byte_us_ = 0;
  uint64_t next_tick_us_ = strider::kTickPeriodUs;
  std::vector<std::string> lines_;
  ChannelPulse pulses_[kMaxChannels];
  bool echo_pending_ = false;
  double echo_at_us_ = 0, echo_width_us_ = 0;
  uint64_t ping_us_ = 0;
};

}  // namespace

std::unique_ptr<Driver> make_library_driver(const strider::RobotModel& model, double osc_hz, RangeFn range,
                                            const GaitOverrides& gait) {
  return std::unique_ptr<Driver>(new LibraryDriver(model, osc_hz, std::move(range), gait));
}

}  // namespace strider_sim
