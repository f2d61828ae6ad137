//! SpeedCorrection: how much of a gait's own body speed each model really
//! makes on the ground, per model and gait, so that a commanded body speed
//! (`walk V`, `turn W`, the RC pad) is the speed the body makes.
//!
//! The gait engine moves the stance feet as if they did not slip; feet that
//! slide (sprawl8's 2-DOF legs swing each stance foot on a circle about its
//! hip while the body goes straight) leave the body short of that speed.
//! WalkerMotion divides the command by the ratio below before it reaches
//! the engine. A pair not listed is taken as slip-free (ratio 1).
//!
//! Measured in the simulator, firmware mode (the model's firmware ELF on the
//! virtual Mega), default friction 0.8 and solver: the gait, then a command
//! held 7 s from standing. Achieved = the steady speed, the displacement
//! (or yaw) from 3 s after the command to its end over that time; sprawl8
//! trot's ratios were taken from the best 2 s window (metrics.json
//! speed_mm_s, yaw_rate_deg_s), which its steady speed confirms within 2 %.
//! tools/sim/measure_speed.py re-measures a pair and prints the ratios for
//! this table. Where a gait's slip is not one ratio over its speeds the
//! entry says over which speeds it holds (docs/results.md).
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
  //! = ratio x the gait's speed - this (each step slides back a little, and
  //! at low speeds the gait steps at its slowest rate, so the loss is one
  //! speed rather than a share of it).
  uint16_t linear_offset;
  //! The fastest body speed the gait makes as commanded [0.1 mm/s] and turn
  //! rate [0.1 deg/s]: the RC pad's 100 % in this gait (RcLimits); 0: the
  //! pad's default (155 mm/s, 60 deg/s), which the gait makes.
  uint16_t top_linear;
  uint16_t top_turn;
};

constexpr uint8_t kSpeedCorrectionCount = 6;

//! In flash on the AVR: read through speed_correction_of().
constexpr SpeedCorrection kSpeedCorrections[kSpeedCorrectionCount] STRIDER_PROGMEM = {
    // sprawl8 trot: walk 155 -> 76.6 mm/s uncorrected (0.494); corrected
    // with it, the gait at 313.8 -> 150.6 mm/s (0.480 at the pad's speed);
    // 0.4697 keeps the pad's 155 mm/s a few % over (seed 000's floor; run
    // to run the firmware's timing moves it ~1 %): the gait at 330 mm/s,
    // where library mode drifts 0.25 % (at 329.8 its trot yawed 8 deg). turn 60 -> 52.7 deg/s;
    // corrected: 60.4 deg/s.
    {"sprawl8", "trot", 4697, 8780, 0, 0, 0},
    // sprawl8 crawl, steady speeds: walk 15.5/31/38/66/82 -> 6.7/14.0/18.7/
    // 26.6/33.1 mm/s (0.43/0.45/0.49/0.40/0.40: the ratio falls above
    // ~25 mm/s, so the pad trots there, gait_choice.h); 0.47 holds the pad's
    // 10 % (15.5 mm/s) and `walk` up to ~25 mm/s within 10 %. turn 6/12/24 ->
    // 5.8/11.8/23.7 deg/s (0.98).
    // Its tops (~33 mm/s, ~29 deg/s) are not the pad's: the pad trots above 25 (gait_choice.h).
    {"sprawl8", "crawl", 4700, 9830, 0, 0, 0},
    // hexapod18 tripod, steady speeds (the pad): the gait at 17.2/34.4/86.1/
    // 172 mm/s -> 12.6/28.3/76.5/161.3 mm/s: 0.927 of the gait's speed less
    // 3.3 mm/s (within 3 % at each). turn 6/12/30 -> 5.3/11.4/28.1 deg/s
    // (0.94 from 12 deg/s up; its limit 37.4-37.5 deg/s: the pad's 100 %
    // turns at 36).
    {"hexapod18", "tripod", 9270, 9450, 33, 0, 360},
    // spider12 walk, steady: the gait at 3.0/6.0/15/17.2/30 mm/s -> 2.2/4.7/
    // 14.0/16.3/27.8 mm/s: 0.948 of it less 0.64 mm/s (its limit 28.0-28.4
    // mm/s at any command above); turn 6/12 -> 5.6/11.7 deg/s (0.96; its
    // limit 12.5-12.6 deg/s). The pad's 100 %: 27 mm/s, 12 deg/s.
    {"spider12", "walk", 9480, 9600, 6, 270, 120},
    // mammal8 walk, not corrected: walk 2/4/10/15.5/20 -> 1.5/3.0/9.5/15.9/
    // 21.4 mm/s (slow steps scatter run to run; its table 5 distances at 15
    // mm/s are within 2 % of the gait's own, SimTargets); its limit
    // 21.3-21.5 mm/s at any command above: the pad's 100 % walks 20 mm/s.
    // Turning in place it hardly moves (0.0-0.1 deg/s): not listed.
    {"mammal8", "walk", 10000, 10000, 0, 200, 0},
    // dog12 trot, not corrected: walk 77.5/155 -> 72.9/114.6 mm/s (its top
    // ~115): the pad's 100 % walks 110 mm/s. Its turn rate falls with the
    // command (6/12/30 -> 4.8/6.5/1.4 deg/s): not listed.
    {"dog12", "trot", 10000, 10000, 0, 1100, 0},
};

//! The ratios of (robot, gait) into *linear and *turn [1/10000]; 10000 for a
//! pair not listed.
inline void speed_correction_of(const char* robot, const char* gait, uint16_t* linear, uint16_t* turn,
                                uint16_t* linear_offset) {
  *linear = 10000;
  *turn = 10000;
  *linear_offset = 0;
  for (uint8_t i = 0; i < kSpeedCorrectionCount; ++i) {
    SpeedCorrection c;
    flash_copy(&c, &kSpeedCorrections[i], sizeof c);
    if (strcmp(c.robot, robot) == 0 && strcmp(c.gait, gait) == 0) {
      *linear = c.linear_per10k;
      *turn = c.turn_per10k;
      *linear_offset = c.linear_offset;
      return;
    }
  }
}

//! The RC pad's 100 % for `robot` walking `gait` into *linear [0.1 mm/s]
//! and *turn [0.1 deg/s]: the gait's top speeds where listed, else left as
//! given (the pad's defaults, control/robot_mode.h's RcLimits).
inline void pad_top_of(const char* robot, const char* gait, int32_t* linear, int32_t* turn) {
  for (uint8_t i = 0; i < kSpeedCorrectionCount; ++i) {
    SpeedCorrection c;
    flash_copy(&c, &kSpeedCorrections[i], sizeof c);
    if (strcmp(c.robot, robot) != 0 || strcmp(c.gait, gait) != 0) continue;
    if (c.top_linear != 0) *linear = c.top_linear;
    if (c.top_turn != 0) *turn = c.top_turn;
    return;
  }
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
