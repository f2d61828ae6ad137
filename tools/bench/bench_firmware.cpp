// Bare-metal benchmark firmware for the ATmega2560 (avr-libc only, no
// Arduino core), run by tools/bench/avr_cycles on simavr.
//
// Each entry runs one function over a fixed set of inputs. Around every call
// the firmware writes GPIOR0 (start) and GPIOR1 (end); the host records the
// cycle counter at both writes. Inputs are prepared before the start marker
// and passed through an empty asm after it, and results are handed to an
// empty asm before the end marker, so the compiler can neither hoist the work
// out of the timed window nor drop it. Protocol: bench_protocol.h.
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/sleep.h>
#include <stdint.h>

#include "bench_gait.h"
#include "bench_legs.h"
#include "bench_protocol.h"
#include "exact_cases.h"
#include "kinematics/body_pose.h"
#include "kinematics/leg_mount.h"
#include "robots/hexapod18.h"
#include "math/fixed.h"
#include "math/scalar.h"

using strider::Fixed;
using strider::IkStatus;
using strider::Vec3;
using namespace strider_bench;

namespace {

uint8_t g_stride = 1;  // 1: every input; quick mode: every 8th

// ---- text channel ---------------------------------------------------------
void put(char c) { GPIOR2 = uint8_t(c); }
void put_P(const char* s) {
  for (char c = char(pgm_read_byte(s)); c != 0; c = char(pgm_read_byte(++s))) put(c);
}
void put_hex(uint32_t v) {
  for (int8_t shift = 28; shift >= 0; shift -= 4) {
    const uint8_t d = uint8_t((v >> shift) & 0xFu);
    put(char(d < 10 ? '0' + d : 'a' + d - 10));
  }
}
void put_dec(uint8_t v) {
  if (v >= 100) put(char('0' + v / 100));
  if (v >= 10) put(char('0' + (v / 10) % 10));
  put(char('0' + v % 10));
}
void put_line_P(char tag, const char* s_P) {
  put(tag);
  put(' ');
  put_P(s_P);
  put('\n');
}

struct TextSink {
  void section(const char* name_P) { put_line_P('S', name_P); }
  void record(const int32_t* v, uint8_t n) {
    put('R');
    for (uint8_t i = 0; i < n; ++i) {
      put(' ');
      put_hex(uint32_t(v[i]));
    }
    put('\n');
  }
};

// ---- keeping the compiler honest ------------------------------------------
template <class S>
struct Pair {
  S a, b;
};

// After the start marker: "the value may have changed" (registers for 4-byte
// scalars, memory for aggregates), so no work can move before the marker.
inline void opaque(float& v) { asm volatile("" : "+r"(v)); }
inline void opaque(Fixed& v) {
  int32_t r = v.raw();
  asm volatile("" : "+r"(r));
  v = Fixed::from_raw(r);
}
template <class S>
inline void opaque(Pair<S>& p) {
  opaque(p.a);
  opaque(p.b);
}
template <class T>
inline void opaque(T& v) { asm volatile("" : : "r"(&v) : "memory"); }

// Before the end marker: "the value is used", so the work is done by then.
inline void keep(float v) { asm volatile("" : : "r"(v)); }
inline void keep(Fixed v) { asm volatile("" : : "r"(v.raw())); }
template <class T>
inline void keep(const T& v) { asm volatile("" : : "r"(&v) : "memory"); }

template <class MakeInput, class Fn>
void bench(const char* name_P, uint8_t count, MakeInput make_input, Fn fn) {
  put_line_P('N', name_P);
  for (uint8_t i = 0; i < count; i = uint8_t(i + g_stride)) {
    auto in = make_input(i);
    GPIOR0 = 1;
    opaque(in);
    const auto out = fn(in);
    keep(out);
    GPIOR1 = 1;
  }
}

// ---- inputs -----------------------------------------------------------------
constexpr uint8_t kMathInputs = 32;

//! Raw input i of a stream: uniform in [lo, hi] [raw Q16.16].
int32_t stream_raw(uint32_t seed, uint8_t i, int32_t lo, int32_t hi) {
  Lcg rng{seed * 7919u + i};
  rng.next();
  return lo + int32_t(rng.next() % uint32_t(hi - lo + 1));
}
template <class S>
S stream(uint32_t seed, uint8_t i, double lo, double hi) {
  return from_raw<S>(stream_raw(seed, i, int32_t(lo * 65536.0), int32_t(hi * 65536.0)));
}

template <class S>
void bench_math(const char* mul_P, const char* div_P, const char* sqrt_P, const char* sin_P, const char* cos_P,
                const char* atan2_P, const char* asin_P, const char* acos_P) {
  // Domains a leg solver uses: lengths to 180 mm, angles within +-pi.
  auto mm_pair = [](uint8_t i) { return Pair<S>{stream<S>(1, i, -180, 180), stream<S>(2, i, -180, 180)}; };
  auto div_pair = [](uint8_t i) {
    const S b = stream<S>(4, i, 1, 180);
    return Pair<S>{stream<S>(3, i, -180, 180), (i & 1) ? -b : b};
  };
  bench(mul_P, kMathInputs, mm_pair, [](const Pair<S>& p) { return p.a * p.b; });
  bench(div_P, kMathInputs, div_pair, [](const Pair<S>& p) { return p.a / p.b; });
  bench(sqrt_P, kMathInputs, [](uint8_t i) { return stream<S>(5, i, 0, 32000); },
        [](S v) { return strider::sqrt(v); });
  bench(sin_P, kMathInputs, [](uint8_t i) { return stream<S>(6, i, -3.1415, 3.1415); },
        [](S v) { return strider::sin(v); });
  bench(cos_P, kMathInputs, [](uint8_t i) { return stream<S>(7, i, -3.1415, 3.1415); },
        [](S v) { return strider::cos(v); });
  bench(atan2_P, kMathInputs, mm_pair, [](const Pair<S>& p) { return strider::atan2(p.a, p.b); });
  bench(asin_P, kMathInputs, [](uint8_t i) { return stream<S>(8, i, -1, 1); },
        [](S v) { return strider::asin(v); });
  bench(acos_P, kMathInputs, [](uint8_t i) { return stream<S>(9, i, -1, 1); },
        [](S v) { return strider::acos(v); });
}

template <class T>
T&& declval_();  // no <utility> on the AVR

template <class Leg>
struct IkResult {
  IkStatus status;
  typename Leg::Joints q;
  decltype(declval_<const Leg&>().fk(declval_<const typename Leg::Joints&>())) reached;
};

//! IK and FK of one leg over its 48 workspace points / grid joint vectors.
template <class Leg>
void bench_leg(const Leg& leg, const char* ik_P, const char* fk_P) {
  bench(ik_P, kGridCount, [&leg](uint8_t i) { return workspace_target(leg, i); },
        [&leg](const decltype(workspace_target(leg, 0))& t) {
          IkResult<Leg> r;
          r.status = leg.ik(t, r.q, r.reached);
          return r;
        });
  bench(fk_P, kGridCount,
        [](uint8_t i) {
          typename Leg::Joints q;
          grid_joints(i, q);
          return q;
        },
        [&leg](const typename Leg::Joints& q) { return leg.fk(q); });
  // Untimed: which IK paths the timed calls took ("I ik_status NAME ok
  // clamped joint_limit unreachable"), so a figure from early exits shows.
  uint8_t count[4] = {0, 0, 0, 0};
  for (uint8_t i = 0; i < kGridCount; i = uint8_t(i + g_stride)) {
    IkResult<Leg> r;
    r.status = leg.ik(workspace_target(leg, i), r.q, r.reached);
    ++count[uint8_t(r.status) & 3u];
  }
  put('I');
  put_P(PSTR(" ik_status "));
  put_P(ik_P);
  for (uint8_t k = 0; k < 4; ++k) {
    put(' ');
    put_dec(count[k]);
  }
  put('\n');
}

// Legs live in RAM like a robot's would; built at reset, not constant-folded.
strider::SprawlLeg<float> g_sprawl_float;
strider::SprawlLeg<Fixed> g_sprawl_fixed;
#if STRIDER_BENCH_HAS_PLANAR_LEG
strider::PlanarLeg<float> g_planar_float;
strider::PlanarLeg<Fixed> g_planar_fixed;
#endif
#if STRIDER_BENCH_HAS_CFT_LEG
strider::CoxaFemurTibiaLeg<float> g_cft_float;
strider::CoxaFemurTibiaLeg<Fixed> g_cft_fixed;
#endif
#if STRIDER_BENCH_HAS_ABDUCTION_LEG
strider::AbductionLeg<float> g_abduction_float;
strider::AbductionLeg<Fixed> g_abduction_fixed;
#endif

//! Body pose: hexapod18's six standing feet seen from a body turned by roll,
//! pitch and yaw and shifted (seed 001 sec. 2.3), each into its leg's frame:
//! what the walker does per tick before the IK when the body is posed.
template <class S>
void bench_body_pose(const char* name_P) {
  static strider::LegMount<S> mounts[6];
  static strider::Vec3<S> feet[6];
  for (uint8_t i = 0; i < 6; ++i) {
    const strider::LegModel& leg = strider::kHexapod18.legs[i];
    mounts[i] = strider::LegMount<S>::make(strider::Vec3<S>::from(leg.mount_mm), S(int(leg.mount_yaw_deg)) * strider::deg_to_rad<S>(1.0));
    feet[i] = strider::Vec3<S>::from(leg.stand_mm);
  }
  auto pose = [](uint8_t i) {
    return strider::BodyPose<S>::make(strider::Vec3<S>(stream<S>(11, i, -20, 20), stream<S>(12, i, -20, 20), stream<S>(13, i, -10, 10)),
                                      stream<S>(14, i, -0.3, 0.3), stream<S>(15, i, -0.3, 0.3), stream<S>(16, i, -0.3, 0.3));
  };
  bench(name_P, kMathInputs, pose, [](const strider::BodyPose<S>& p) {
    const strider::Transform<S> body = strider::body_transform(p);
    strider::Vec3<S> sum;
    for (uint8_t k = 0; k < 6; ++k) sum = sum + mounts[k].body_to_leg(strider::foot_in_body(body, feet[k]));
    return sum;
  });
}

void run_bench() {
  // Empty window: the marker overhead the host subtracts.
  bench(PSTR("baseline"), kMathInputs, [](uint8_t i) { return from_raw<Fixed>(i); }, [](Fixed v) { return v; });
  bench_math<Fixed>(PSTR("fixed_mul"), PSTR("fixed_div"), PSTR("fixed_sqrt"), PSTR("fixed_sin"), PSTR("fixed_cos"),
                    PSTR("fixed_atan2"), PSTR("fixed_asin"), PSTR("fixed_acos"));
  bench_math<float>(PSTR("float_mul"), PSTR("float_div"), PSTR("float_sqrt"), PSTR("float_sin"), PSTR("float_cos"),
                    PSTR("float_atan2"), PSTR("float_asin"), PSTR("float_acos"));
#if STRIDER_BENCH_HAS_CFT_LEG
  g_cft_float = make_hexapod_leg<float>();
  g_cft_fixed = make_hexapod_leg<Fixed>();
  bench_leg(g_cft_float, PSTR("coxa_femur_tibia_ik_float"), PSTR("coxa_femur_tibia_fk_float"));
  bench_leg(g_cft_fixed, PSTR("coxa_femur_tibia_ik_fixed"), PSTR("coxa_femur_tibia_fk_fixed"));
#endif
  g_sprawl_float = make_sprawl_leg<float>();
  g_sprawl_fixed = make_sprawl_leg<Fixed>();
  bench_leg(g_sprawl_float, PSTR("sprawl_ik_float"), PSTR("sprawl_fk_float"));
  bench_leg(g_sprawl_fixed, PSTR("sprawl_ik_fixed"), PSTR("sprawl_fk_fixed"));
#if STRIDER_BENCH_HAS_PLANAR_LEG
  g_planar_float = make_planar_leg<float>();
  g_planar_fixed = make_planar_leg<Fixed>();
  bench_leg(g_planar_float, PSTR("planar_ik_float"), PSTR("planar_fk_float"));
  bench_leg(g_planar_fixed, PSTR("planar_ik_fixed"), PSTR("planar_fk_fixed"));
#endif
#if STRIDER_BENCH_HAS_ABDUCTION_LEG
  g_abduction_float = make_abduction_leg<float>();
  g_abduction_fixed = make_abduction_leg<Fixed>();
  bench_leg(g_abduction_float, PSTR("abduction_ik_float"), PSTR("abduction_fk_float"));
  bench_leg(g_abduction_fixed, PSTR("abduction_ik_fixed"), PSTR("abduction_fk_fixed"));
#endif
  bench_body_pose<Fixed>(PSTR("body_pose_6_legs_fixed"));
  bench_body_pose<float>(PSTR("body_pose_6_legs_float"));
  run_gait_bench(g_stride);
}

}  // namespace

int main() {
  // The host preloads the mode into GPIOR2 before reset; crt0 leaves it alone.
  const uint8_t mode = GPIOR2;
  if (mode & STRIDER_BENCH_MODE_QUICK) g_stride = 8;
  put_line_P('I', PSTR("firmware strider_bench"));
  if (!(mode & STRIDER_BENCH_MODE_NO_BENCH)) run_bench();
  if (!(mode & STRIDER_BENCH_MODE_NO_EXACT)) {
    TextSink sink;
    run_exact_cases(sink);
  }
  put('E');
  put('\n');
  // Sleeping with interrupts off ends the simulation.
  cli();
  sleep_enable();
  for (;;) sleep_cpu();
}
