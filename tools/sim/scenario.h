// Scenario: a simulator run described as text (docs/simulator.md):
//   robot sprawl8
//   duration 20                      # seconds of simulated time
//   obstacle box X Y SX SY SZ        # mm; axis-aligned box on the ground, centre at X,Y
//   at T send TEXT                   # at T seconds, send TEXT to the Bluetooth link; \n \r escapes
//   imu on                           # an MPU-6050 is fitted (firmware mode: vbench's, fed by the IMU model)
// One directive per line; `#` starts a comment; blank lines are ignored.
#pragma once

#include <string>
#include <vector>

#include "world.h"

namespace strider_sim {

struct TimedSend {
  double at_s = 0;
  std::string bytes;  // escapes already decoded
};

struct Scenario {
  std::string robot;
  double duration_s = 0;
  std::vector<ObstacleBox> obstacles;
  std::vector<TimedSend> sends;  // sorted by time (stable)
  bool imu = false;              // `imu on`
};

// Parses scenario text. On error returns false and sets *error to
// "line N: reason".
bool parse_scenario(const std::string& text, Scenario* out, std::string* error);
bool load_scenario(const std::string& path, Scenario* out, std::string* error);

// Decodes \n, \r, \t, \\ and \xHH in a send text.
bool decode_escapes(const std::string& in, std::string* out);

}  // namespace strider_sim
