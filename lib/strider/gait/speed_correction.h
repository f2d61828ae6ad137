//! SpeedCorrection: how much of a gait's own body speed each model really
//! makes on the ground (feet slide), per model and gait: WalkerMotion divides
//! a command (`walk V`, `turn W`, the RC pad) by it so that the body makes the
//! speed commanded; a pair not listed is slip-free (ratio 1). Measured in the
//! simulator, firmware mode (tools/sim/measure_speed.py; docs/results.md).
#ifndef STRIDER_GAIT_SPEED_CORRECTION_H
#define STRIDER_GAIT_SPEED_CORRECTION_H

#include <stdint.h>
#include <string.h>

#include "../math/flash_table.h"
#include "gait_table.h"

namespace strider {

struct SpeedCorrection {
  char robot[10];                //!< model name (as kGaitParams)
  char gait[kGaitNameBytes];     //!< gait name (gait_library.h)
  uint16_t linear_per10k;      //!< achieved / commanded forward speed [1/10000]
  uint16_t turn_per10k;        //!< achieved / commanded turn rate [1/10000]
  //! The body speed the gait's steps lose at any speed [0.1 mm/s]: achieved
  //! = ratio x the gait's speed - this.
  uint16_t linear_offset;
  //! The RC pad's 100 % in this gait (RcLimits) [0.1 mm/s], [0.1 deg/s]; 0:
  //! the pad's default (155 mm/s, 60 deg/s), which the gait makes.
  uint16_t top_linear;
  uint16_t top_turn;
};

constexpr uint8_t kSpeedCorrectionCount = 6;

constexpr SpeedCorrection kSpeedCorrections[kSpeedCorrectionCount] STRIDER_PROGMEM = {
    // sprawl8 trot: walk 155 -> 76.6 mm/s uncorrected (0.494); 0.4697 keeps
    // the pad's 155 mm/s a few % over (the gait at 330 mm/s). turn 60 -> 52.7 deg/s.
    {"sprawl8", "trot", 4697, 8780, 0, 0, 0},
    // sprawl8 crawl: walk 15.5/31/38/66/82 -> 6.7/14.0/18.7/26.6/33.1 mm/s
    // (0.43-0.49, 0.40 above ~25 mm/s, where the pad trots: gait_choice.h);
    // 0.47 holds to ~25 mm/s within 10 %. turn 6/12/24 -> 5.8/11.8/23.7 deg/s.
    {"sprawl8", "crawl", 4700, 9830, 0, 0, 0},
    // hexapod18 tripod: the gait at 17.2/34.4/86.1/172 mm/s -> 12.6/28.3/
    // 76.5/161.3 mm/s (0.927 less 3.3 mm/s); turn 6/12/30 -> 5.3/11.4/28.1
    // deg/s, its limit 37.4 deg/s (the pad's 100 % turns at 36).
    {"hexapod18", "tripod", 9270, 9450, 33, 0, 360},
    // spider12 walk: the gait at 3.0/6.0/15/17.2/30 mm/s -> 2.2/4.7/14.0/
    // 16.3/27.8 mm/s (0.948 less 0.64 mm/s, its limit 28 mm/s); turn 6/12 ->
    // 5.6/11.7 deg/s (its limit 12.5 deg/s).
    {"spider12", "walk", 9480, 9600, 6, 270, 120},
    // mammal8 walk, not corrected: walk 2/4/10/15.5/20 -> 1.5/3.0/9.5/15.9/
    // 21.4 mm/s, its limit 21.4 mm/s; turning in place it hardly moves.
    {"mammal8", "walk", 10000, 10000, 0, 200, 0},
    // dog12 crawl: the gait at 17/30/70/137 mm/s -> 8.9/24.1/69/115.5 mm/s;
    // turn 2.2/4.4/11/22 -> 1.4/3.9/9/19.4 deg/s (its limits 144, 23.5).
    {"dog12", "crawl", 9000, 9100, 35, 1200, 200},
};

//! The entry of (robot, gait) into *c; false for a pair not listed.
inline bool speed_correction_entry(const char* robot, const char* gait, SpeedCorrection* c) {
  for (uint8_t i = 0; i < kSpeedCorrectionCount; ++i) {
    flash_copy(c, &kSpeedCorrections[i], sizeof *c);
    if (strcmp(c->robot, robot) == 0 && strcmp(c->gait, gait) == 0) return true;
  }
  return false;
}

//! The ratios of (robot, gait) into *linear and *turn [1/10000]; 10000 for a
//! pair not listed.
inline void speed_correction_of(const char* robot, const char* gait, uint16_t* linear, uint16_t* turn,
                                uint16_t* linear_offset) {
  SpeedCorrection c;
  const bool listed = speed_correction_entry(robot, gait, &c);
  *linear = listed ? c.linear_per10k : 10000;
  *turn = listed ? c.turn_per10k : 10000;
  *linear_offset = listed ? c.linear_offset : 0;
}

//! The RC pad's 100 % for `robot` walking `gait` into *linear [0.1 mm/s]
//! and *turn [0.1 deg/s]: the gait's top speeds where listed, else left as
//! given (the pad's defaults, control/robot_mode.h's RcLimits).
inline void pad_top_of(const char* robot, const char* gait, int32_t* linear, int32_t* turn) {
  SpeedCorrection c;
  if (!speed_correction_entry(robot, gait, &c)) return;
  if (c.top_linear != 0) *linear = c.top_linear;
  if (c.top_turn != 0) *turn = c.top_turn;
}

//! A commanded body speed -> the gait's own speed that makes it:
//! (v + offset) / ratio away from zero, rounded to the nearest [0.1 mm/s]
//! (or [0.1 deg/s]); 0 stays 0.
inline int32_t speed_corrected(int32_t v, uint16_t per10k, uint16_t offset = 0) {
  if (v == 0) return 0;
  const int64_t n = (int64_t(v) + (v < 0 ? -int64_t(offset) : int64_t(offset))) * 10000;
  if (per10k == 0) return int32_t(n / 10000);
  return int32_t((n + (n < 0 ? -int64_t(per10k / 2) : int64_t(per10k / 2))) / per10k);
}

//! The gait's own speed -> the body speed it makes: ratio x g less the
//! offset towards zero (0 where the offset is more).
inline int32_t body_speed_of(int32_t g, uint16_t per10k, uint16_t offset = 0) {
  const int32_t b = per10k == 0 ? g : int32_t(int64_t(g) * per10k / 10000);
  if (b > int32_t(offset)) return b - int32_t(offset);
  if (b < -int32_t(offset)) return b + int32_t(offset);
  return 0;
}

}  // namespace strider

#endif  // STRIDER_GAIT_SPEED_CORRECTION_H
