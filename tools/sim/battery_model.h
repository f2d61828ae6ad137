// BatteryModel: the robot's pack, sagging under the servos' current and
// draining over time, and the divider that brings it to an analog pin
// (docs/imu.md has the model and its figures).
//
// Servos (servo_supply_current_a): each servo's DC motor from its data sheet
// at the supply voltage V: winding resistance R = V / I_stall, back-EMF
// constant k_e = V / w_noload and torque constant k_t = tau_stall / I_stall
// (both at the output shaft, so the gearbox is inside them). Holding or
// moving with torque tau at speed w the motor carries I = |tau| / k_t and
// needs V_m = I R + k_e w' (w' = w along the torque: positive when it drives,
// negative when it is driven back and brakes), at most V; its PWM bridge
// draws max(0, V_m I) / V from the supply, plus the electronics' idle
// current.
// A servo without pulses draws its idle current only.
//
// Pack: n LiPo cells in series with an internal resistance (cells, wiring,
// connectors). Its open-circuit voltage follows the state of charge along a
// LiPo resting-voltage table (4.20 V a cell full, 3.82 V at half, 3.27 V
// empty); the servos run from a BEC (switching, efficiency eta) at V_servo,
// the Mega and the boards draw a constant logic current from the pack
// through the Mega's linear regulator. With P = P_servos / eta the pack
// voltage under load solves V = V_oc - R (P / V + I_logic); the charge drops
// by the pack current times dt.
#pragma once

#include <cmath>  // servo_model.h uses M_PI

#include "robots/robot_model.h"
#include "robots/servo_parts.h"
#include "servo_model.h"

namespace strider_sim {

// A servo's electrical figures at 6 V: stall current (Tower Pro MG996R: 2.5 A,
// its data sheet; the others are estimates for their motor size where the
// sheet gives none) and idle current (10 mA; Hitec HS-311: 7.7 mA).
struct ServoElectrical {
  double stall_current_a = 1.0;
  double idle_current_a = 0.01;
};
ServoElectrical servo_electrical(strider::ServoPart part);

// Supply current of one servo [A] (see above); servo: its torque and speed
// figures (servo_model.h), supply_v: the BEC's output [V].
double servo_supply_current_a(const ServoModel& servo, const ServoElectrical& e, double torque_nm, double speed_rad_s,
                              bool on, double supply_v = 6.0);

// Open-circuit voltage of one LiPo cell at state of charge soc (0..1) [V].
double lipo_cell_ocv(double soc);

struct BatteryConfig {
  int cells = 2;                 // 2S LiPo, 7.4 V nominal
  double capacity_mah = 2200;
  double internal_ohm = 0.06;    // 2 cells of ~15 mOhm, 30 mOhm of wiring and connectors
  double soc = 1.0;              // state of charge at power-up (1 = full, 8.4 V at rest)
  double servo_volts = 6.0;      // BEC output
  double bec_efficiency = 0.85;  // a switching UBEC
  double logic_current_a = 0.15; // Mega, PCA9685 logic, HC-05, HC-SR04, from the pack
  double divider = 3.0;          // pack volts per pin volt: 20 kOhm over 10 kOhm
  int adc_pin = 0;               // A0
};

// The pack a model's robot carries by default: the 2S 2200 mAh above, and for
// dog12 (twelve 60 kg cm servos, 5.2 kg) a 3S 5000 mAh pack of 40 mOhm.
BatteryConfig battery_for(const strider::RobotModel& model);

class BatteryModel {
 public:
  explicit BatteryModel(const BatteryConfig& config = BatteryConfig());
  // One step of dt [s] with the servos drawing servo_current_a at servo_volts.
  void step(double servo_current_a, double dt);
  double volts() const { return volts_; }           // at the terminals, under load [V]
  double open_circuit_volts() const;                // [V]
  double current_a() const { return current_a_; }   // out of the pack [A]
  double soc() const { return soc_; }
  double used_mah() const { return used_mah_; }
  double pin_volts() const { return volts_ / config_.divider; }  // at the analog pin [V]
  // The load was more than the pack can give (V below half its open-circuit value).
  bool collapsed() const { return collapsed_; }
  const BatteryConfig& config() const { return config_; }

 private:
  BatteryConfig config_;
  double soc_;
  double volts_;
  double current_a_ = 0;
  double used_mah_ = 0;
  bool collapsed_ = false;
};

}  // namespace strider_sim
