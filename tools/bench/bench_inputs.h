//! Inputs shared by the benchmark firmware and the host bit-exact test: leg
//! geometries, workspace points as exact integers (quarter millimetres, so
//! float and Fixed hold them exactly on both machines), and a 32-bit LCG that
//! gives the same stream on the AVR and the host.
#ifndef STRIDER_TOOLS_BENCH_INPUTS_H
#define STRIDER_TOOLS_BENCH_INPUTS_H

#include <stdint.h>

#include "math/fixed.h"

#if defined(__AVR__)
#include <avr/pgmspace.h>
#define STRIDER_BENCH_FLASH PROGMEM
#else
#define STRIDER_BENCH_FLASH
#endif

namespace strider_bench {

//! Reads a table element (flash on the AVR, RAM on the host).
inline int16_t read_i16(const int16_t* p) {
#if defined(__AVR__)
  return int16_t(pgm_read_word(p));
#else
  return *p;
#endif
}

//! Numerical Recipes LCG: uint32 arithmetic wraps identically everywhere.
struct Lcg {
  uint32_t state;
  uint32_t next() {
    state = state * 1664525u + 1013904223u;
    return state;
  }
  //! A raw Q16.16 value whose magnitude spreads over 2^-16 .. 2^15.
  int32_t any_raw() {
    const uint8_t shift = uint8_t(next() >> 27);  // 0..31
    return int32_t(next()) >> (shift > 24 ? 24 : shift);
  }
  //! A raw value uniform in [-span, span] (span > 0) [raw units].
  int32_t within(int32_t span) {
    return int32_t(next() % (2u * uint32_t(span) + 1u)) - span;
  }
};

// Seed 002 hexapod leg: d1 = 32, coxa 30, femur 85, tibia 125 mm.
constexpr int kHexD1Mm = 32;
constexpr int kHexCoxaMm = 30;
constexpr int kHexFemurMm = 85;
constexpr int kHexTibiaMm = 125;

//! 48 foot targets of the seed 002 leg in its frame 0 [0.25 mm]: seed 002
//! eqs 5-7 at theta1 in {-30,-10,10,30} deg, theta2 in {-10,5,20,35} deg,
//! theta3 in {-75,-95,-115} deg, rounded to 0.25 mm.
constexpr uint8_t kHexTargetCount = 48;
const int16_t kHexTargetsQmm[kHexTargetCount][3] STRIDER_BENCH_FLASH = {
    {432, -249, -429}, {282, -163, -414}, {146, -84, -341}, {545, -315, -312},
    {397, -229, -342}, {249, -144, -312}, {629, -363, -165}, {493, -284, -239},
    {343, -198, -254}, {677, -391, 2},    {562, -324, -110}, {420, -243, -169},
    {491, -87, -429},  {320, -57, -414},  {165, -29, -341},  {620, -109, -312},
    {452, -80, -342},  {283, -50, -312},  {715, -126, -165}, {560, -99, -239},
    {390, -69, -254},  {770, -136, 2},    {639, -113, -110}, {478, -84, -169},
    {491, 87, -429},   {320, 57, -414},   {165, 29, -341},   {620, 109, -312},
    {452, 80, -342},   {283, 50, -312},   {715, 126, -165},  {560, 99, -239},
    {390, 69, -254},   {770, 136, 2},     {639, 113, -110},  {478, 84, -169},
    {432, 249, -429},  {282, 163, -414},  {146, 84, -341},   {545, 315, -312},
    {397, 229, -342},  {249, 144, -312},  {629, 363, -165},  {493, 284, -239},
    {343, 198, -254},  {677, 391, 2},     {562, 324, -110},  {420, 243, -169},
};

//! A quarter-millimetre integer as a raw Q16.16 value (exact).
constexpr int32_t qmm_to_raw(int16_t qmm) { return int32_t(qmm) * 16384; }

//! Joint grid used for the forward-kinematics entries [mrad]: 4 x 4 x 3
//! angles, the first two reused by the 2-DOF legs.
constexpr uint8_t kGridCount = 48;
const int16_t kJointGridA[4] STRIDER_BENCH_FLASH = {-524, -175, 175, 524};
const int16_t kJointGridB[4] STRIDER_BENCH_FLASH = {-175, 87, 349, 611};
const int16_t kJointGridC[3] STRIDER_BENCH_FLASH = {-1309, -1658, -2007};

//! Milliradians as a raw Q16.16 value: round(mrad * 65536 / 1000), exact
//! integer arithmetic (|mrad| < 32768).
constexpr int32_t mrad_to_raw(int16_t mrad) {
  return mrad >= 0 ? (int32_t(mrad) * 65536 + 500) / 1000 : -((-int32_t(mrad) * 65536 + 500) / 1000);
}

//! Joint angles number i (0..47) of the grid [raw Q16.16].
inline void grid_joints_raw(uint8_t i, int32_t out[3]) {
  out[0] = mrad_to_raw(read_i16(&kJointGridA[i / 12]));
  out[1] = mrad_to_raw(read_i16(&kJointGridB[(i / 3) % 4]));
  out[2] = mrad_to_raw(read_i16(&kJointGridC[i % 3]));
}

}  // namespace strider_bench

#endif  // STRIDER_TOOLS_BENCH_INPUTS_H
