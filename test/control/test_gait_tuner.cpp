// Live gait parameters through the whole RobotApp (control/gait_tuner.h),
// every model, float and Fixed: `get` shows the model's own values; `set`
// within the walker's bounds changes the walk at the next stride (a new
// step height in the swings that lift afterwards, a new cycle in the step
// rate, a new duty in the table walked) and outside them is refused with
// the range and changes nothing; `save` keeps them per gait in EEPROM
// across a power cycle, a gait switch takes each gait's own; an image
// without the tuning record (older firmware), a corrupt record, a saved
// value the walker no longer allows, and a save cut at any byte all leave
// a walker that is either the old or the new one, never a mix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "control/robot_app.h"
#include "gait/gait_presets.h"
#include "fakes/fake_store.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "robots/all_robots.h"

namespace {

struct Lines {
  std::vector<std::string> sent;
  void send_line(uint8_t, const char* line) { sent.emplace_back(line); }
};

// A robot on a store that outlives it (a power cycle: a new app, the same EEPROM).
template <typename S, typename Store = strider_test::FakeStore>
struct Robot {
  using App = strider::RobotApp<S, strider_test::RecordingServo, Store>;
  strider_test::RecordingServo out;
  Lines lines;
  std::unique_ptr<App> app;
  uint32_t now_us = 1000;

  Robot(const strider::RobotModel& m, Store& store) : app(new App(m, out, store)) {
    EXPECT_TRUE(app->begin(now_us, lines));
  }
  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; t += 20) {
      now_us += strider::kTickPeriodUs;
      app->tick(now_us, lines);
      out.writes.clear();
    }
  }
  std::string say(const std::string& line) {
    const size_t from = lines.sent.size();
    for (unsigned char b : line + "\n") app->on_byte(1, b, now_us, lines);
    EXPECT_EQ(lines.sent.size(), from + 1) << line;
    return lines.sent.size() > from ? lines.sent.back() : std::string();
  }
  std::string field(const std::string& reply, const std::string& key) {
    const size_t at = reply.find(" " + key + "=");
    if (at == std::string::npos) return "";
    const size_t from = at + key.size() + 2;
    return reply.substr(from, reply.find(' ', from) - from);
  }
  strider::GaitEngine<S>& engine() { return app->motion().walker().engine(); }
};

std::string hundredths(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

template <typename S>
class GaitTunerTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(GaitTunerTest, Scalars);

TYPED_TEST(GaitTunerTest, GetShowsTheModelsOwnValues) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    strider_test::FakeStore store;
    Robot<TypeParam> r(*m, store);
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    const std::string get = r.say("get");
    EXPECT_EQ(get.rfind("ok get gait=" + std::string(p.default_gait) + " ", 0), 0u) << get;
    EXPECT_EQ(r.field(get, "step_height"), hundredths(p.step_height_mm)) << get;
    EXPECT_EQ(r.field(get, "step_length"), hundredths(p.step_length_mm)) << get;
    EXPECT_EQ(r.field(get, "cycle"), hundredths(p.cycle_s)) << get;
    EXPECT_EQ(r.field(get, "swing"), strider::to_string(p.shape)) << get;
    strider::GaitTable own;
    ASSERT_TRUE(strider::load_gait(*m, p.default_gait, &own));
    EXPECT_NEAR(std::stod(r.field(get, "duty")), own.duty, 0.01) << get;
    EXPECT_NEAR(std::stod(r.field(get, "height")), -m->legs[0].stand_mm.z, 0.05) << get;
    EXPECT_EQ(r.say("status").find(" tune="), std::string::npos);  // the model's own: no field
    std::printf("%-9s %s\n", m->name, get.c_str());
  }
}

TYPED_TEST(GaitTunerTest, RefusedValuesNameTheRangeAndChangeNothing) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    strider_test::FakeStore store;
    Robot<TypeParam> r(*m, store);
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    const std::string before = r.say("get");
    const std::string high = "set step_height " + hundredths(p.step_height_mm + 0.01);
    EXPECT_EQ(r.say(high), "err 25 step_height out of range: 1.00.." + hundredths(p.step_height_mm)) << high;
    EXPECT_EQ(r.say("set step_height 0.99").rfind("err 25 step_height out of range: 1.00..", 0), 0u);
    EXPECT_EQ(r.say("set cycle 5.01").rfind("err 25 cycle out of range: ", 0), 0u);
    EXPECT_EQ(r.say("set cycle 0.01").rfind("err 25 cycle out of range: ", 0), 0u);
    EXPECT_EQ(r.say("set step_length 4.99").rfind("err 25 step_length out of range: 5.00..", 0), 0u);
    EXPECT_EQ(r.say("set duty 0.96").rfind("err 25 duty out of range: ", 0), 0u);
    const std::string swing = r.say("set swing bezier");
    if (p.shape != strider::SwingShape::kBezier) {
      EXPECT_EQ(swing.rfind("err 25 swing not under the model's own swing: ", 0), 0u) << swing;
    }
    EXPECT_EQ(r.say("set wobble 3"), "err 2 bad argument: set step_height|step_length|cycle|duty VALUE, set swing "
                                     "rectangle|semicircle|ellipse|cycloid|parabola|bezier");
    EXPECT_EQ(r.say("set swing zigzag").rfind("err 2 bad argument: set ", 0), 0u);
    EXPECT_EQ(r.say("set cycle").rfind("err 3 missing argument: set ", 0), 0u);
    EXPECT_EQ(r.say("set cycle 1 2").rfind("err 4 too many arguments: set ", 0), 0u);
    EXPECT_EQ(r.say("get 1").rfind("err 4 too many arguments", 0), 0u);
    EXPECT_EQ(r.say("get"), before);
  }
}

// What `get` shows is what the robot walks, and each value it shows is one
// `set` takes back, in every gait of every model: a gait whose share down
// leaves the servos too little swing time at the model's cycle (sprawl8's
// walk, hexapod18's wave) shows the longer cycle it steps at. Setting the
// values back changes nothing: no tune, the same servo pulses.
TYPED_TEST(GaitTunerTest, EveryGaitsOwnValuesAreOnesSetTakes) {
  using S = TypeParam;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    std::string gaits = strider::gait_names(m->leg_count);
    for (size_t from = 0; from < gaits.size();) {
      const size_t end = std::min(gaits.find(' ', from), gaits.size());
      const std::string gait = gaits.substr(from, end - from);
      from = end + 1;
      SCOPED_TRACE(std::string(m->name) + " " + gait);
      strider_test::FakeStore store;
      Robot<S> r(*m, store);
      EXPECT_EQ(r.say("gait " + gait), "ok gait " + gait);
      const std::string get = r.say("get");
      const strider::VelocityLimits<S>& lim = r.engine().config().limits;
      const double cycle = std::stod(r.field(get, "cycle")), duty = std::stod(r.field(get, "duty"));
      // The servos' swing fits the cycle shown: (1 - duty) cycle >= lift.
      EXPECT_GE((1.0 - duty) * cycle * 1000.0, strider::to_double(lim.lift_ms) - 0.5) << get;
      const strider::GaitConfig<S> before = r.engine().config();
      for (const char* key : {"duty", "cycle", "step_height", "step_length", "swing"})
        EXPECT_EQ(r.say(std::string("set ") + key + " " + r.field(get, key)),
                  std::string("ok set ") + key + " " + r.field(get, key));
      EXPECT_EQ(r.say("get"), get);
      EXPECT_TRUE(r.engine().config().limits.min_hz == before.limits.min_hz);
      EXPECT_TRUE(r.engine().config().step_height_mm == before.step_height_mm);
      EXPECT_TRUE(r.engine().config().limits.preferred_stride_mm == before.limits.preferred_stride_mm);
    }
  }
}

// The cycle's range depends on the duty and the duty's on the cycle: a
// longer share down needs a longer cycle first (err 25 names the duties the
// cycle set allows), and a saved pair that is only allowed together loads.
TYPED_TEST(GaitTunerTest, DutyAndCycleAreCheckedTogether) {
  using S = TypeParam;
  const strider::RobotModel& m = strider::kSprawl8;  // crawl, cycle 0.80, duty 0.67
  strider_test::FakeStore store;
  std::string saved;
  {
    Robot<S> r(m, store);
    const std::string refused = r.say("set duty 0.90");
    EXPECT_EQ(refused.rfind("err 25 duty out of range: 0.51..0.7", 0), 0u) << refused;
    const std::string cycle = r.say("set cycle 0.60");  // too short for duty 0.90 later
    EXPECT_EQ(cycle, "ok set cycle 0.60");
    EXPECT_EQ(r.say("set duty 0.90").rfind("err 25 duty out of range: ", 0), 0u);
    EXPECT_EQ(r.say("set cycle 2.50"), "ok set cycle 2.50");
    EXPECT_EQ(r.say("set duty 0.90"), "ok set duty 0.90");
    // Now the cycle cannot go back below what duty 0.90 leaves the swing.
    const std::string short_cycle = r.say("set cycle 0.80");
    EXPECT_EQ(short_cycle.rfind("err 25 cycle out of range: 1.", 0), 0u) << short_cycle;
    EXPECT_EQ(r.say("save"), "ok saved");
    saved = r.say("get");
  }
  Robot<S> again(m, store);
  EXPECT_EQ(again.say("get"), saved);
  EXPECT_EQ(again.field(again.say("status"), "tune"), "saved");
}

// A lower step lifts in less servo time (velocity_search.h's lift_ms grows
// with the apex; the tuner scales it with the step height set): mammal8's
// trot with its 20 mm steps and a 0.90 s cycle takes duty 0.73 at most, with
// 5 mm steps 0.80 (its trot50 preset) and shorter cycles; the step rate the
// walk plans at 60 mm/s rises with it.
TYPED_TEST(GaitTunerTest, ALowerStepLetsTheServosStepFaster) {
  using S = TypeParam;
  strider_test::FakeStore store;
  Robot<S> r(strider::kMammal8, store);
  EXPECT_EQ(r.say("gait trot"), "ok gait trot");
  EXPECT_EQ(r.say("set cycle 0.90"), "ok set cycle 0.90");
  const std::string refused = r.say("set duty 0.80");
  EXPECT_EQ(refused.rfind("err 25 duty out of range: 0.50..0.73", 0), 0u) << refused;
  EXPECT_EQ(r.say("set duty 0.73"), "ok set duty 0.73");
  const std::string high = r.say("set cycle 0.10");  // refused: names the shortest cycle
  r.engine().set_command(S(60), S(0), S(0));
  const double hz_high = strider::to_double(r.engine().target_plan().step_hz);
  EXPECT_EQ(r.say("set step_height 5"), "ok set step_height 5.00");
  const std::string low = r.say("set cycle 0.10");
  const double hz_low = strider::to_double(r.engine().target_plan().step_hz);
  EXPECT_LT(std::stod(low.substr(low.rfind(": ") + 2)), std::stod(high.substr(high.rfind(": ") + 2))) << low << " | " << high;
  EXPECT_GT(hz_low, 1.2 * hz_high);
  EXPECT_EQ(r.say("set duty 0.80"), "ok set duty 0.80");
  // The model's own step height again: its own lift, the ranges as before.
  EXPECT_EQ(r.say("set duty 0.73"), "ok set duty 0.73");
  EXPECT_EQ(r.say("set step_height 20"), "ok set step_height 20.00");
  EXPECT_EQ(r.say("set cycle 0.10"), high);
  r.engine().set_command(S(0), S(0), S(0));
}

// Each model walks its default gait; a lower step height reaches the swings
// that lift after it, not the ones in the air; a shorter cycle raises the
// step rate at low speed; a new duty is the table walked.
TYPED_TEST(GaitTunerTest, ChangesReachTheWalkAtTheNextStride) {
  using S = TypeParam;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    strider_test::FakeStore store, twin_store;
    Robot<S> r(*m, store);
    Robot<S> twin(*m, twin_store);  // walks the same without the change
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    for (Robot<S>* x : {&r, &twin}) {
      x->say("deadman 60000");
      x->run_ms(3000);  // stands up
      x->say("walk 10");
    }
    // Highest lift over the ground of any foot per tick, over `ms`.
    const auto lift = [&](uint32_t ms) {
      double top = 0;
      for (uint32_t t = 0; t < ms; t += 20) {
        r.run_ms(20);
        twin.run_ms(20);
        for (uint8_t i = 0; i < m->leg_count; ++i)
          top = std::fmax(top, strider::to_double(r.engine().foot(i).z - r.engine().config().home[i].z));
      }
      return top;
    };
    const uint32_t cycle_ms = uint32_t(p.cycle_s * 1000);
    EXPECT_NEAR(lift(2 * cycle_ms), p.step_height_mm, 0.6);  // the apex between two ticks
    lift(cycle_ms / 4 / 20 * 20);  // mid-swing for some foot
    std::vector<bool> in_air(m->leg_count);
    bool any = false;
    for (uint8_t i = 0; i < m->leg_count; ++i) any = any || (in_air[i] = !r.engine().contact(i));
    ASSERT_TRUE(any);
    const double low = std::floor(p.step_height_mm * 50) / 100;  // about half, two decimals
    EXPECT_EQ(r.say("set step_height " + hundredths(low)), "ok set step_height " + hundredths(low));
    EXPECT_NEAR(strider::to_double(r.engine().config().step_height_mm), low, 0.01);
    const std::string swing = p.shape == strider::SwingShape::kCycloid ? "parabola" : "cycloid";
    EXPECT_EQ(r.say("set swing " + swing), "ok set swing " + swing);
    // Feet in the air finish their swing as they began it, to the tick.
    for (int t = 0; t < 200; ++t) {
      lift(20);
      bool still = false;
      for (uint8_t i = 0; i < m->leg_count; ++i) {
        if (!in_air[i]) continue;
        if (r.engine().contact(i)) {
          in_air[i] = false;
          continue;
        }
        still = true;
        EXPECT_EQ(strider::to_double(r.engine().foot(i).z), strider::to_double(twin.engine().foot(i).z)) << "leg " << int(i) << " tick " << t;
      }
      if (!still) break;
    }
    r.run_ms(cycle_ms);  // every foot has landed and lifted again
    EXPECT_NEAR(lift(2 * cycle_ms), low, 0.6);
    EXPECT_EQ(r.field(r.say("status"), "tune"), "changed");

    const double hz_before = strider::to_double(r.engine().step_hz());
    EXPECT_NEAR(hz_before, 1.0 / p.cycle_s, 0.01);
    // About 80 %, or between the shortest the servos allow and the model's own.
    double shorter = std::ceil(p.cycle_s * 80) / 100;
    const std::string refused = "err 25 cycle out of range: ";
    const std::string reply = r.say("set cycle " + hundredths(shorter));
    if (reply.rfind(refused, 0) == 0) {
      const double lo = std::stod(reply.substr(refused.size()));
      ASSERT_LT(lo, p.cycle_s) << reply;
      shorter = std::ceil((lo + p.cycle_s) * 50) / 100;
      EXPECT_EQ(r.say("set cycle " + hundredths(shorter)), "ok set cycle " + hundredths(shorter));
    } else {
      EXPECT_EQ(reply, "ok set cycle " + hundredths(shorter));
    }
    r.run_ms(3 * cycle_ms);  // along the ramp
    // Faster, up to the new cycle's rate (the servos may allow less at this stride).
    const double hz = strider::to_double(r.engine().step_hz());
    EXPECT_GT(hz, hz_before + 0.02);
    EXPECT_LE(hz, 1.0 / shorter + 1e-3);
    std::printf("%-9s step height %.2f -> %.2f mm, cycle %.2f -> %.2f s: %.3f -> %.3f Hz at 10 mm/s\n", m->name,
                double(p.step_height_mm), low, double(p.cycle_s), shorter, hz_before, hz);

    const strider::TuneRange duties = r.app->tune_bounds().duty;  // the gait's, at the cycle set
    const int32_t duty = (duties.lo + duties.hi) / 2;
    EXPECT_EQ(r.say("set duty " + hundredths(duty / 100.0)), "ok set duty " + hundredths(duty / 100.0));
    EXPECT_NEAR(double(r.engine().gait().duty), duty / 100.0, 1e-6);
    r.run_ms(2 * cycle_ms);
    EXPECT_EQ(r.field(r.say("status"), "state"), "walking");
    r.say("stop");
    r.run_ms(3 * cycle_ms);
    EXPECT_EQ(r.field(r.say("status"), "state"), "standing");
  }
}

TYPED_TEST(GaitTunerTest, SavedPerGaitAcrossAPowerCycle) {
  using S = TypeParam;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    strider_test::FakeStore store;
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    const std::string other = m->leg_count == 6 ? "ripple" : std::string(p.default_gait) == "trot" ? "walk" : "trot";
    const std::string low = hundredths(std::floor(p.step_height_mm * 60) / 100);
    std::string saved_get, other_get;
    {
      Robot<S> r(*m, store);
      EXPECT_EQ(r.say("set step_height " + low), "ok set step_height " + low);
      EXPECT_EQ(r.say("set step_length " + hundredths(p.step_length_mm * 0.75)).rfind("ok set", 0), 0u);
      EXPECT_EQ(r.say("set cycle " + hundredths(p.cycle_s + 0.1)).rfind("ok set", 0), 0u);
      EXPECT_EQ(r.say("set swing cycloid"), "ok set swing cycloid");  // under every model's own
      r.run_ms(3000);
      EXPECT_EQ(r.say("save"), "ok saved");
      saved_get = r.say("get");
      EXPECT_EQ(r.field(r.say("status"), "tune"), "saved");
      // Another gait: its own values (the model's), its own saved ones after a save.
      EXPECT_EQ(r.say("gait " + other), "ok gait " + other);
      other_get = r.say("get");
      EXPECT_EQ(r.field(other_get, "step_height"), hundredths(p.step_height_mm)) << other_get;
      EXPECT_EQ(r.say("set cycle " + hundredths(p.cycle_s + 0.2)).rfind("ok set", 0), 0u);
      EXPECT_EQ(r.say("save"), "ok saved");
      other_get = r.say("get");
      EXPECT_EQ(r.say("gait " + std::string(p.default_gait)), "ok gait " + std::string(p.default_gait));
      EXPECT_EQ(r.say("get"), saved_get);
    }
    Robot<S> again(*m, store);  // power cycle: the default gait's saved values
    EXPECT_EQ(again.say("get"), saved_get);
    EXPECT_EQ(again.field(again.say("status"), "tune"), "saved");
    EXPECT_NEAR(strider::to_double(again.engine().config().step_height_mm), std::stod(low), 0.01);
    EXPECT_EQ(again.engine().config().shape, strider::SwingShape::kCycloid);
    EXPECT_EQ(again.say("gait " + other), "ok gait " + other);
    EXPECT_EQ(again.say("get"), other_get);
  }
}

// A model's presets (gait_presets.h) are picked like gaits: `gait trot10`
// walks the trot with the preset's parameters, which `get` shows; every
// preset of every model is accepted by its walker; another model does not
// have them (err 23, its gaits named).
TYPED_TEST(GaitTunerTest, PresetsWalkTheirGaitWithTheirParameters) {
  using S = TypeParam;
  for (uint8_t i = 0; i < strider::kGaitPresetCount; ++i) {
    const strider::GaitPreset& p = strider::kGaitPresets[i];
    SCOPED_TRACE(std::string(p.robot) + " " + p.name);
    strider_test::FakeStore store;
    Robot<S> r(*strider::find_robot(p.robot), store);
    EXPECT_EQ(r.say(std::string("gait ") + p.name), std::string("ok gait ") + p.name);
    const std::string get = r.say("get");
    EXPECT_EQ(r.field(get, "gait"), p.gait);
    if (p.step_length_cmm != 0) {
      EXPECT_EQ(std::lround(100 * std::stod(r.field(get, "step_length"))), p.step_length_cmm);
    }
    if (p.step_height_cmm != 0) {
      EXPECT_EQ(std::lround(100 * std::stod(r.field(get, "step_height"))), p.step_height_cmm);
    }
    if (p.cycle_cs != 0) {
      EXPECT_EQ(std::lround(100 * std::stod(r.field(get, "cycle"))), p.cycle_cs);
    }
    if (p.duty_pct != 0) {
      EXPECT_EQ(std::lround(100 * std::stod(r.field(get, "duty"))), p.duty_pct);
    }
    EXPECT_NE(r.say("status").find(" tune=changed"), std::string::npos);
  }
  strider_test::FakeStore store;
  Robot<S> other(strider::kSprawl8, store);
  EXPECT_EQ(other.say("gait trot10"), "err 23 unknown gait: walk trot pace crawl");
}

// A preset listed in speed_correction.h by its name (mammal8's pace10) walks
// with that correction: `walk 3.1` keeps vx=3.1 (and walk_vx=3.1, the body
// speed the gait makes) and walks the gait at 3.1 / 0.866 = 3.6; the same walk in
// trot10 (not listed) walks the gait as commanded; a `set` afterwards leaves
// the preset's parameters and its correction with them.
TYPED_TEST(GaitTunerTest, APresetWalksWithItsOwnSpeedCorrection) {
  using S = TypeParam;
  strider_test::FakeStore store;
  Robot<S> r(strider::kMammal8, store);
  r.run_ms(3000);
  EXPECT_EQ(r.say("$deadman off*cb77").rfind("ok", 0), 0u);  // no keep-alives here
  const auto walked = [&r](const char* gait, const char* set) {
    EXPECT_EQ(r.say(std::string("gait ") + gait), std::string("ok gait ") + gait);
    if (set != nullptr) EXPECT_EQ(r.say(set).rfind("ok set", 0), 0u);
    EXPECT_EQ(r.say("walk 3.1").rfind("ok", 0), 0u);
    r.run_ms(6000);  // the ramp
    const std::string st = r.say("status");
    EXPECT_EQ(r.field(st, "vx"), "3.1") << st;
    EXPECT_EQ(r.field(st, "walk_vx"), "3.1") << st;
    const double gait_mm_s = strider::to_double(r.engine().vx());
    EXPECT_EQ(r.say("stop").rfind("ok", 0), 0u);
    r.run_ms(6000);
    return gait_mm_s;
  };
  EXPECT_NEAR(walked("pace10", nullptr), 3.6, 0.01);  // 3.58 to the correction's 0.1 mm/s
  EXPECT_NEAR(walked("pace10", "set step_height 4.00"), 3.1, 0.01);
  EXPECT_NEAR(walked("trot10", nullptr), 3.1, 0.01);
}

// A save's bytes: the tuning record after the settings (the settings load as
// before: its layout version and place are unchanged). An image of older
// firmware has those bytes erased: the model's own values, eeprom=ok.
TYPED_TEST(GaitTunerTest, OlderImagesCorruptOrDisallowedRecordsLoadTheDefaults) {
  using S = TypeParam;
  const strider::RobotModel& m = strider::kSprawl8;
  strider_test::FakeStore store;
  std::string own_get;
  {
    Robot<S> r(m, store);
    own_get = r.say("get");
    EXPECT_EQ(r.say("speed 70"), "ok speed pct=70");
    EXPECT_EQ(r.say("set step_height 12.50"), "ok set step_height 12.50");
    EXPECT_EQ(r.say("save"), "ok saved");
  }
  strider_test::FakeStore older = store;  // the tuning slots erased: what older firmware left
  for (uint16_t a = strider::kGaitTuningBase; a < strider::kGaitTuningStoreEnd; ++a) older.bytes[a] = 0xFF;
  {
    Robot<S> r(m, older);
    EXPECT_EQ(r.lines.sent[1].rfind("info eeprom ok", 0), 0u) << r.lines.sent[1];
    EXPECT_EQ(r.say("get"), own_get);
    EXPECT_EQ(r.field(r.say("status"), "speed"), "70");
  }
  const strider::GaitTuningSlot slot = strider::find_gait_tuning(store);
  ASSERT_NE(slot.slot, strider::kNoSettingsSlot);
  strider_test::FakeStore corrupt = store;
  corrupt.bytes[strider::kGaitTuningBase + slot.slot * strider::kGaitTuningSlotBytes + 8] ^= 0x10;
  {
    Robot<S> r(m, corrupt);
    EXPECT_EQ(r.say("get"), own_get);
  }
  // A whole record whose value this walker does not allow (another build's).
  strider_test::FakeStore disallowed = store;
  strider::GaitTuning t{4000, 4000, 80, 67, uint8_t(strider::SwingShape::kEllipse), 0};
  ASSERT_EQ(strider::save_gait_tuning(disallowed, strider::gait_index(4, "crawl"), t), strider::SettingsStatus::kOk);
  {
    Robot<S> r(m, disallowed);
    EXPECT_EQ(r.say("get"), own_get);
  }
}

// A store that loses power at its n-th write (that byte left as it was).
struct CutStore : strider::ArrayByteStore<4096> {
  int cut_at = -1;
  int writes = 0;
  bool write(uint16_t addr, uint8_t v) {
    const int n = writes++;
    if (cut_at >= 0 && n >= cut_at) return false;
    return ArrayByteStore<4096>::write(addr, v);
  }
};

TEST(GaitTuningRecord, ASaveCutAtAnyByteKeepsTheOldOrTheNewEntry) {
  CutStore before;
  before.erase();
  const strider::GaitTuning old_t{1500, 3000, 80, 67, 2, 700};
  const strider::GaitTuning new_t{1000, 2500, 60, 70, 3, 650};
  const strider::GaitTuning trot_t{1200, 2000, 50, 55, 3, 0};
  ASSERT_EQ(strider::save_gait_tuning(before, 3, old_t), strider::SettingsStatus::kOk);
  ASSERT_EQ(strider::save_gait_tuning(before, 1, trot_t), strider::SettingsStatus::kOk);
  CutStore whole = before;
  whole.writes = 0;
  ASSERT_EQ(strider::save_gait_tuning(whole, 3, new_t), strider::SettingsStatus::kOk);
  const int total = whole.writes;
  EXPECT_EQ(total, int(strider::kGaitTuningRecordBytes) + 1);  // the first byte twice
  for (int cut = 0; cut <= total; ++cut) {
    CutStore s = before;
    s.writes = 0;
    s.cut_at = cut;
    const strider::SettingsStatus st = strider::save_gait_tuning(s, 3, new_t);
    EXPECT_EQ(st == strider::SettingsStatus::kOk, cut == total) << cut;
    strider::GaitTuning got{}, trot{};
    ASSERT_TRUE(strider::read_gait_tuning(s, 3, &got)) << cut;
    const strider::GaitTuning& want = cut == total ? new_t : old_t;
    EXPECT_EQ(std::memcmp(&got, &want, sizeof got), 0) << cut;
    ASSERT_TRUE(strider::read_gait_tuning(s, 1, &trot)) << cut;  // the other gait's entry survives either way
    EXPECT_EQ(std::memcmp(&trot, &trot_t, sizeof trot), 0) << cut;
    strider::GaitTuning none{};
    EXPECT_FALSE(strider::read_gait_tuning(s, 0, &none)) << cut;  // never saved
  }
  strider::ArrayByteStore<160> small;
  small.erase();
  EXPECT_EQ(strider::save_gait_tuning(small, 0, old_t), strider::SettingsStatus::kNoSpace);
}

}  // namespace
