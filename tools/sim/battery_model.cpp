// BatteryModel and the servos' supply current (see battery_model.h).
#include "battery_model.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace strider_sim {

ServoElectrical servo_electrical(strider::ServoPart part) {
  switch (part) {
    case strider::ServoPart::kSg90: return {0.65, 0.01};
    case strider::ServoPart::kMg90s: return {0.75, 0.01};
    case strider::ServoPart::kMg995: return {2.0, 0.01};
    case strider::ServoPart::kMg996r: return {2.5, 0.01};
    case strider::ServoPart::kHs311: return {0.8, 0.0077};
    case strider::ServoPart::kDs3235: return {3.0, 0.01};
    case strider::ServoPart::kDs5160: return {4.5, 0.01};
  }
  return {};
}

double servo_supply_current_a(const ServoModel& servo, const ServoElectrical& e, double torque_nm, double speed_rad_s,
                              bool on, double supply_v) {
  if (!on || servo.torque_nm <= 0 || servo.speed_rad_s <= 0 || e.stall_current_a <= 0) return e.idle_current_a;
  const double r = supply_v / e.stall_current_a;
  const double k_e = supply_v / servo.speed_rad_s;
  const double k_t = servo.torque_nm / e.stall_current_a;
  const double i = std::fabs(torque_nm) / k_t;
  const double along = torque_nm >= 0 ? speed_rad_s : -speed_rad_s;
  // The bridge cannot give the motor more than the supply (duty <= 1).
  const double v_motor = std::min(supply_v, i * r + k_e * along);
  return e.idle_current_a + std::max(0.0, v_motor * i) / supply_v;
}

BatteryConfig battery_for(const strider::RobotModel& model) {
  BatteryConfig c;
  if (std::string(model.name) == "dog12") {  // twelve 60 kg cm servos: a 3S 5000 mAh pack
    c.cells = 3;
    c.capacity_mah = 5000;
    c.internal_ohm = 0.04;
  }
  return c;
}

double lipo_cell_ocv(double soc) {
  // Resting voltage of a LiPo cell at 0, 10, ..., 100 % charge.
  static const double kOcv[11] = {3.27, 3.69, 3.73, 3.77, 3.79, 3.82, 3.87, 3.92, 3.98, 4.06, 4.20};
  const double s = std::min(1.0, std::max(0.0, soc)) * 10.0;
  const int k = std::min(9, int(s));
  return kOcv[k] + (kOcv[k + 1] - kOcv[k]) * (s - k);
}

BatteryModel::BatteryModel(const BatteryConfig& config) : config_(config), soc_(config.soc) {
  volts_ = open_circuit_volts();
}

double BatteryModel::open_circuit_volts() const { return config_.cells * lipo_cell_ocv(soc_); }

void BatteryModel::step(double servo_current_a, double dt) {
  const double voc = open_circuit_volts();
  const double p = std::max(0.0, servo_current_a) * config_.servo_volts / config_.bec_efficiency;
  const double r = config_.internal_ohm;
  // V = Voc - R (P / V + I_logic)  <=>  V^2 - (Voc - R I_logic) V + R P = 0.
  const double b = voc - r * config_.logic_current_a;
  const double disc = b * b - 4 * r * p;
  collapsed_ = disc < 0;
  volts_ = collapsed_ ? b / 2 : (b + std::sqrt(disc)) / 2;
  current_a_ = (voc - volts_) / r;
  if (r <= 0) {
    volts_ = voc;
    current_a_ = p / std::max(voc, 1e-9) + config_.logic_current_a;
  }
  const double mah = current_a_ * dt / 3.6;
  used_mah_ += mah;
  soc_ = std::max(0.0, soc_ - mah / config_.capacity_mah);
}

}  // namespace strider_sim
