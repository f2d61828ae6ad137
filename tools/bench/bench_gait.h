// The whole control tick on the simulated ATmega2560, per robot model:
// Walker<S>::tick (gait engine, body pose, reach projection, leg IK), the
// servo frame (joint angles -> PCA9685 ticks for every joint) and both
// together, walking forward in the model's default gait from standing; plus
// Walker::configure() and the RAM the walker takes.
//
// Entries (S = fixed, float), one call per tick of 20 ms:
//   walker_configure_<model>_S  Walker::configure(model, gait, params, shape)
//   walker_tick_<model>_S       Walker::tick(0.02)
//   gait_engine_tick_<model>_S  its first part, GaitEngine::tick(0.02)
//   servo_frame_<model>_S       write_servo_frame of every joint (ServoTickMap)
//   control_tick_<model>_S      both, into a servo output that drops the data
//   set_command_<model>_S       GaitEngine::set_command() while walking (the
//                               plan of a new command: half / full speed,
//                               with and without turning, every other tick)
// Info lines: "size NAME BYTES" (sizeof of the walker's parts), and after
// each timed walk "walk <model>_S h h ..." (gait_scenario.h's walk_record,
// hex), which test/avr compares with the host's replay.
//
// Included by bench_firmware.cpp (run_gait_bench() from its run_bench());
// self-contained so that it does not depend on the firmware's own functions.
#ifndef STRIDER_TOOLS_BENCH_GAIT_H
#define STRIDER_TOOLS_BENCH_GAIT_H

#include <avr/io.h>
#include <avr/pgmspace.h>
#include <stddef.h>
#include <stdint.h>

#include "control/servo_frame.h"
#include "gait_scenario.h"

// Placement new (no <new> on the AVR): the walkers share one buffer.
inline void* operator new(size_t, void* where) noexcept { return where; }

namespace strider_bench {
namespace gait_bench {

using strider::Fixed;


inline void put(char c) { GPIOR2 = uint8_t(c); }
inline void put_P(const char* s) {
  for (char c = char(pgm_read_byte(s)); c != 0; c = char(pgm_read_byte(++s))) put(c);
}
inline void put_str(const char* s) {
  for (; *s != 0; ++s) put(*s);
}
inline void put_u16(uint16_t v) {
  char buf[6];
  uint8_t n = 0;
  do {
    buf[n++] = char('0' + v % 10u);
    v = uint16_t(v / 10u);
  } while (v != 0);
  while (n > 0) put(buf[--n]);
}
//! "N <what>_<model>_<scalar>": an entry begins.
inline void begin_entry(const char* what_P, const char* model, const char* scalar_P) {
  put('N');
  put(' ');
  put_P(what_P);
  put('_');
  put_str(model);
  put('_');
  put_P(scalar_P);
  put('\n');
}
inline void put_size(const char* name_P, const char* scalar_P, uint16_t bytes) {
  put('I');
  put_P(PSTR(" size "));
  put_P(name_P);
  put('_');
  put_P(scalar_P);
  put(' ');
  put_u16(bytes);
  put('\n');
}

inline void start() {
  GPIOR0 = 1;
  asm volatile("" ::: "memory");
}
inline void stop() {
  asm volatile("" ::: "memory");
  GPIOR1 = 1;
}

//! A servo output that keeps nothing (the bus write is not the CPU's work).
struct NullServoOutput {
  uint16_t sum = 0;
  void write_ticks(uint8_t channel, uint16_t ticks) { sum = uint16_t(sum + channel + ticks); }
  void set_prescale(uint8_t) {}
};

//! The channels of a model: joint j of leg i on channel i * dof + j, centred
//! on the middle of the joint's range, limits at its ends; right legs mirrored.
template <typename S>
void make_channels(const strider::RobotModel& m, strider::ServoChannel<S>* ch) {
  const uint8_t dof = m.dof();
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    for (uint8_t j = 0; j < dof; ++j) {
      const strider::JointRange& r = m.legs[i].joint[j];
      const double mid = 0.5 * (double(r.min_deg) + double(r.max_deg));
      double half = 0.5 * (double(r.max_deg) - double(r.min_deg));
      if (half > 90.0) half = 90.0;
      const int8_t dir = m.legs[i].side == strider::BodySide::kLeft ? 1 : -1;
      ch[i * dof + j] = strider::make_servo_channel<S>(uint8_t(i * dof + j), dir, mid, half, half);
    }
  }
}

template <typename S>
struct GaitRig {
  // The walker first: its configure() may need more stack than is left
  // and run into the end of this object, so what lies there is set up
  // after it.
  strider::Walker<S> walker;
  const strider::RobotModel* model = nullptr;
  S vx = S(0);
  NullServoOutput out;
  strider::Pca9685Timing timing;
  strider::ServoTickMap<S> tick_map;

  void init_frame() {
    out = NullServoOutput();
    timing = strider::Pca9685Timing();
    strider::ServoChannel<S> channels[strider::kMaxLegs * strider::kMaxLegDof];
    make_channels(*model, channels);
    tick_map = strider::ServoTickMap<S>();
    tick_map.configure(channels, model->joint_count(), strider::default_settings(), timing);
  }

  //! Back to standing (the configuration built before), then the command.
  void restart() { scenario_restart(walker, *model, vx); }

  //! Every joint through the folded map (servo_tick_map.h).
  strider::ServoStatus frame() {
    const uint8_t dof = model->dof();
    strider::ServoStatus worst = strider::ServoStatus::kOk;
    for (uint8_t i = 0; i < model->leg_count; ++i) {
      const strider::ServoStatus s =
          strider::write_servo_frame(out, tick_map, &walker.leg(i).q[0], dof, uint8_t(i * dof));
      worst = strider::worst(worst, s);
    }
    return worst;
  }

};

inline void put_hex(uint32_t v) {
  for (int8_t shift = 28; shift >= 0; shift -= 4) {
    const uint8_t d = uint8_t((v >> shift) & 0xFu);
    put(char(d < 10 ? '0' + d : 'a' + d - 10));
  }
}

//! "I walk <model>_<scalar> h h ...": the state after a timed walk.
template <typename S>
void put_walk(const strider::Walker<S>& w, const char* model, const char* scalar_P) {
  int32_t v[kWalkRecordMax];
  const uint8_t n = walk_record(w, v);
  put('I');
  put_P(PSTR(" walk "));
  put_str(model);
  put('_');
  put_P(scalar_P);
  for (uint8_t i = 0; i < n; ++i) {
    put(' ');
    put_hex(uint32_t(v[i]));
  }
  put('\n');
}

template <typename S>
void bench_model(void* storage, const strider::RobotModel& m, const char* scalar_P, uint8_t stride) {
  strider::GaitTable gait;
  if (!scenario_gait(m, &gait)) return;
  GaitRig<S>& rig = *new (storage) GaitRig<S>();
  const S dt = strider::scalar<S>(0.02);

  begin_entry(PSTR("walker_configure"), m.name, scalar_P);
  start();
  const bool ok = scenario_configure(rig.walker, m);
  stop();
  if (!ok) return;
  rig.model = &m;
  rig.init_frame();
  rig.vx = scenario_speed(rig.walker);

  const uint16_t ticks = uint16_t(kGaitTicks / stride);
  rig.restart();
  begin_entry(PSTR("walker_tick"), m.name, scalar_P);
  for (uint16_t k = 0; k < ticks; ++k) {
    start();
    rig.walker.tick(dt);
    stop();
  }
  put_walk(rig.walker, m.name, scalar_P);
  rig.restart();
  begin_entry(PSTR("gait_engine_tick"), m.name, scalar_P);
  for (uint16_t k = 0; k < ticks; ++k) {
    start();
    rig.walker.engine().tick(dt);
    stop();
  }
  rig.restart();
  begin_entry(PSTR("servo_frame"), m.name, scalar_P);
  for (uint16_t k = 0; k < ticks; ++k) {
    rig.walker.tick(dt);
    start();
    const strider::ServoStatus s = rig.frame();
    stop();
    asm volatile("" : : "r"(uint8_t(s)));
  }
  rig.restart();
  begin_entry(PSTR("control_tick"), m.name, scalar_P);
  for (uint16_t k = 0; k < ticks; ++k) {
    start();
    rig.walker.tick(dt);
    const strider::ServoStatus s = rig.frame();
    stop();
    asm volatile("" : : "r"(uint8_t(s)));
  }
  // Command changes from the middle of the walk on.
  rig.restart();
  for (uint16_t k = 0; k < ticks / 2; ++k) rig.walker.tick(dt);
  begin_entry(PSTR("set_command"), m.name, scalar_P);
  const uint8_t changes = uint8_t(32 / stride);
  for (uint8_t k = 0; k < changes; ++k) {
    const S v = (k & 1) ? rig.vx : rig.vx * strider::scalar<S>(0.5);
    const S wz = (k & 2) ? strider::scalar<S>(0.3) : S(0);
    start();
    rig.walker.engine().set_command(v, S(0), wz);
    stop();
    rig.walker.tick(dt);
    rig.walker.tick(dt);
  }
  rig.~GaitRig<S>();
}

template <typename S>
void put_sizes(const char* scalar_P) {
  put_size(PSTR("walker"), scalar_P, sizeof(strider::Walker<S>));
  put_size(PSTR("gait_engine"), scalar_P, sizeof(strider::GaitEngine<S>));
  put_size(PSTR("gait_config"), scalar_P, sizeof(strider::GaitConfig<S>));
  put_size(PSTR("velocity_limits"), scalar_P, sizeof(strider::VelocityLimits<S>));
  put_size(PSTR("any_leg"), scalar_P, sizeof(strider::AnyLeg<S>));
  put_size(PSTR("leg_result"), scalar_P, sizeof(strider::LegResult<S>));
  put_size(PSTR("support_polygon"), scalar_P, sizeof(strider::SupportPolygon<S>));
  put_size(PSTR("servo_tick_map"), scalar_P, sizeof(strider::ServoTickMap<S>));
}

constexpr size_t kStorage =
    sizeof(GaitRig<Fixed>) > sizeof(GaitRig<float>) ? sizeof(GaitRig<Fixed>) : sizeof(GaitRig<float>);
// One buffer for whichever rig runs (both at once would not fit in 8 KB).
alignas(4) uint8_t g_storage[kStorage];

}  // namespace gait_bench

//! Every model: configure, walker tick, servo frame and control tick, for
//! Fixed then float; stride 8 in quick mode (fewer ticks).
inline void run_gait_bench(uint8_t stride) {
  namespace g = gait_bench;
  using strider::Fixed;
  g::put_sizes<Fixed>(PSTR("fixed"));
  g::put_sizes<float>(PSTR("float"));
  for (const strider::RobotModel* m : strider::kAllRobots) {
    g::bench_model<Fixed>(g::g_storage, *m, PSTR("fixed"), stride);
    g::bench_model<float>(g::g_storage, *m, PSTR("float"), stride);
  }
}

}  // namespace strider_bench

#endif  // STRIDER_TOOLS_BENCH_GAIT_H
