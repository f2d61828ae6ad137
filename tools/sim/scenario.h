// Scenario: a simulator run described as text (docs/simulator.md):
//   robot sprawl8
//   duration 20                      # seconds of simulated time
//   obstacle box X Y SX SY SZ        # mm; axis-aligned box on the ground, centre at X,Y
//   at T send TEXT                   # at T seconds, send TEXT to the Bluetooth link; \n \r escapes
//   feet pad MM                      # feet as capsules across the leg, MM to each side (--foot-pad wins)
//   imu on                           # an MPU-6050 is fitted (firmware mode: vbench's, fed by the IMU model)
//   ramp DEG [UPHILL_DEG]            # the ground slopes DEG, rising toward UPHILL_DEG (0: +x, 90: +y)
//   battery cells N mah C ohm R soc S  # the pack (any of the four keys, in any order)
//   at T shove X Y Z                 # an impulse [N s], world frame, at the top of the body
//   at T upright                     # the robot set back on its feet, sitting, where it lies
//   at T ramp DEG [UPHILL_DEG]       # the ground tilts to a slope from then on (0: flat again)
// One directive per line; `#` starts a comment; blank lines are ignored.
#pragma once

#include <string>
#include <vector>

#include "sim_sensors.h"
#include "world.h"

namespace strider_sim {

struct TimedSend {
  double at_s = 0;
  std::string bytes;  // escapes already decoded
};

// `at T shove X Y Z`, `at T upright` and `at T ramp DEG [UPHILL_DEG]`:
// something done to the robot or its ground.
struct TimedEvent {
  enum Kind { kShove, kUpright, kRamp };
  double at_s = 0;
  Kind kind = kShove;
  Vec impulse_ns;               // kShove: world frame [N s]
  double ramp_deg = 0;          // kRamp: the slope [deg]
  double ramp_uphill_deg = 0;   // kRamp: the direction it rises toward [deg]
};

struct Scenario {
  std::string robot;
  double duration_s = 0;
  std::vector<ObstacleBox> obstacles;
  std::vector<TimedSend> sends;  // sorted by time (stable)
  double foot_pad_half_mm = 0;   // `feet pad MM`; 0: the model's ball feet
  bool imu = false;              // `imu on`
  double ramp_deg = 0;           // `ramp DEG [UPHILL_DEG]`: the ground's slope [deg]
  double ramp_uphill_deg = 0;    // the direction it rises toward, world frame [deg]
  BatteryOverrides battery;      // `battery ...`; the command line's options win
  std::vector<TimedEvent> events;  // sorted by time (stable)
};

// Parses scenario text. On error returns false and sets *error to
// "line N: reason".
bool parse_scenario(const std::string& text, Scenario* out, std::string* error);
bool load_scenario(const std::string& path, Scenario* out, std::string* error);

// Decodes \n, \r, \t, \\ and \xHH in a send text.
bool decode_escapes(const std::string& in, std::string* out);

}  // namespace strider_sim
