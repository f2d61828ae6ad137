// Sonar filter (echo -> mm, range limits, median outlier rejection, missing
// echoes, staleness), obstacle avoidance sequences with a manual clock, and
// the deadman timer.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "control/avoidance.h"
#include "control/deadman.h"
#include "control/sonar_echo.h"
#include "control/sonar_filter.h"
#include "fakes/manual_clock.h"
#include "fakes/scripted_sonar.h"

using strider::AvoidState;
using strider::SonarFilter;
using strider::SonarReading;
using strider::SonarStatus;
using strider::Twist;
using strider_test::ManualClock;
using strider_test::ScriptedSonar;

namespace {

// Runs the non-blocking ping cycle for ms milliseconds in 10 ms ticks.
void run_sonar(SonarFilter& f, ScriptedSonar& s, ManualClock& clk, uint32_t ms) {
  for (uint32_t t = 0; t < ms; t += 10) {
    if (f.ping_due(clk.now_us())) s.trigger(clk.now_us());
    strider::EchoSample e;
    if (s.poll(&e)) f.add(e, clk.now_us());
    clk.advance_ms(10);
  }
}

TEST(Sonar, EchoToMillimetres) {
  EXPECT_EQ(strider::echo_to_mm(0), 0u);
  EXPECT_EQ(strider::echo_to_mm(1166), 200u);   // 20 cm: seed 000's avoidance distance
  EXPECT_EQ(strider::echo_to_mm(17493), 3000u); // 300 cm: the sensor's range
  EXPECT_EQ(strider::echo_to_mm(65535), 11239u);
}

TEST(Sonar, RangeLimits) {
  struct Case {
    uint16_t width_us;
    uint16_t expect_mm;
  };
  const Case table[] = {{58, strider::kSonarMinMm},   // 10 mm: nearer than 2 cm -> 20 mm
                        {117, 20},
                        {5831, 1000},
                        {17493, 3000},
                        {17500, strider::kSonarFarMm},  // beyond 300 cm: clear
                        {38000, strider::kSonarFarMm}}; // the sensor's "nothing" pulse
  for (const Case& c : table) {
    SonarFilter f;
    for (int i = 0; i < 5; ++i) f.add(strider::EchoSample{strider::EchoKind::kEcho, c.width_us, 0}, 0);
    const SonarReading r = f.reading(0);
    EXPECT_EQ(r.status, SonarStatus::kOk);
    EXPECT_EQ(r.distance_mm, c.expect_mm) << c.width_us;
  }
}

TEST(Sonar, MedianRejectsOutliers) {
  ManualClock clk;
  SonarFilter f;
  ScriptedSonar s;
  const uint16_t w500 = ScriptedSonar::width_for_mm(500);
  s.script = {w500, w500, ScriptedSonar::width_for_mm(30), w500, 40000, w500, w500, ScriptedSonar::width_for_mm(90),
              ScriptedSonar::width_for_mm(95), w500};
  uint32_t pings = 0;
  for (int i = 0; i < 100; ++i) {
    if (f.ping_due(clk.now_us())) {
      s.trigger(clk.now_us());
      ++pings;
    }
    strider::EchoSample e;
    if (s.poll(&e)) f.add(e, clk.now_us());
    const SonarReading r = f.reading(clk.now_us());
    if (r.status == SonarStatus::kOk) {
      EXPECT_GE(r.distance_mm, 497) << "ping " << pings;  // one or two outliers in 5 never win
      EXPECT_LE(r.distance_mm, 500) << "ping " << pings;
    }
    clk.advance_ms(6);
  }
  EXPECT_EQ(pings, 10u);  // 600 ms at one ping per 60 ms: non-blocking, rate-limited
}

TEST(Sonar, MissingEchoesFailThenRecover) {
  ManualClock clk;
  SonarFilter f;
  ScriptedSonar s;
  const uint16_t w = ScriptedSonar::width_for_mm(800);
  s.script = {w, w, w, 0, 0, 0, 0};
  run_sonar(f, s, clk, 60 * 3 + 60 * 3);  // 3 echoes, then 3 missing: held
  SonarReading r = f.reading(clk.now_us());
  EXPECT_EQ(r.status, SonarStatus::kOk);
  EXPECT_EQ(r.distance_mm, 800);
  run_sonar(f, s, clk, 60 * 2);  // 5 missing in a row
  r = f.reading(clk.now_us());
  EXPECT_EQ(r.status, SonarStatus::kFailed);
  s.script.push_back(w);
  s.next = s.script.size() - 1;
  run_sonar(f, s, clk, 60);
  EXPECT_EQ(f.reading(clk.now_us()).status, SonarStatus::kOk);
}

TEST(Sonar, NoDataAndStale) {
  SonarFilter f;
  EXPECT_EQ(f.reading(0).status, SonarStatus::kNoData);
  f.add(strider::EchoSample{strider::EchoKind::kEcho, 2000, 0}, 0);
  f.add(strider::EchoSample{strider::EchoKind::kEcho, 2000, 0}, 1000);
  EXPECT_EQ(f.reading(1000).status, SonarStatus::kNoData);  // 2 of 5: not enough
  f.add(strider::EchoSample{strider::EchoKind::kEcho, 2000, 0}, 2000);
  EXPECT_EQ(f.reading(2000).status, SonarStatus::kOk);
  EXPECT_EQ(f.reading(2000 + strider::kSonarStaleUs + 1).status, SonarStatus::kStale);
  // Clock wrap: stamps just before and after 2^32 us.
  SonarFilter g;
  for (uint32_t k = 0; k < 5; ++k) g.add(strider::EchoSample{strider::EchoKind::kEcho, 2000, 0}, 0xFFFFFF00u + k * 100u);
  EXPECT_EQ(g.reading(0x00000100u).status, SonarStatus::kOk);
}

TEST(SonarEcho, EdgesToSamples) {
  strider::SonarEcho e;
  strider::EchoSample s{};
  EXPECT_FALSE(e.poll(0, &s));
  // A normal echo: rise 450 us after TRIG, 1166 us wide (20 cm).
  e.triggered(1000);
  EXPECT_TRUE(e.busy());
  e.edge(true, 1450);
  EXPECT_FALSE(e.poll(2000, &s));
  e.edge(false, 1450 + 1166);
  ASSERT_TRUE(e.poll(3000, &s));
  EXPECT_EQ(s.kind, strider::EchoKind::kEcho);
  EXPECT_EQ(s.width_us, 1166);
  EXPECT_EQ(s.at_us, 1000u);
  EXPECT_FALSE(e.poll(3001, &s));  // once per ping
  // Missing echo: no rising edge before the deadline.
  e.triggered(10000);
  EXPECT_FALSE(e.poll(10000 + strider::kEchoStartDeadlineUs, &s));
  ASSERT_TRUE(e.poll(10001 + strider::kEchoStartDeadlineUs, &s));
  EXPECT_EQ(s.kind, strider::EchoKind::kNoEdge);
  // Stuck high: reported as far after kEchoMaxWidthUs.
  e.triggered(100000);
  e.edge(true, 100500);
  ASSERT_TRUE(e.poll(100501 + strider::kEchoMaxWidthUs, &s));
  EXPECT_EQ(s.width_us, 0xFFFF);
  // Stray edges while idle are ignored; a falling edge first is ignored.
  e.edge(false, 200000);
  e.edge(true, 200010);
  EXPECT_FALSE(e.poll(200020, &s));
  e.triggered(300000);
  e.edge(false, 300100);
  e.edge(true, 300200);
  e.edge(false, 300200 + 5831);
  ASSERT_TRUE(e.poll(310000, &s));
  EXPECT_EQ(strider::echo_to_mm(s.width_us), 1000u);
  // Across the 32-bit microsecond wrap.
  e.triggered(0xFFFFFF00u);
  e.edge(true, 0xFFFFFF80u);
  e.edge(false, 0x00000100u);
  ASSERT_TRUE(e.poll(0x00000200u, &s));
  EXPECT_EQ(s.width_us, 0x180);
  // The interrupt stamped the rising edge after the loop read its time: the
  // ping is still in flight, not 71 minutes long (found on the virtual Mega).
  e.triggered(500000);
  e.edge(true, 500600);
  EXPECT_FALSE(e.poll(500550, &s));
  EXPECT_TRUE(e.busy());
  e.edge(false, 500600 + 1166);
  ASSERT_TRUE(e.poll(500590, &s));
  EXPECT_EQ(s.width_us, 1166);
  // Likewise for the trigger's deadline.
  e.triggered(600000);
  EXPECT_FALSE(e.poll(599990, &s));
}

SonarReading at(uint16_t mm) { return SonarReading{SonarStatus::kOk, mm}; }

TEST(Avoidance, SeedSequenceSidestepThenResume) {
  strider::Avoidance a;
  const auto cfg = strider::default_avoid_config();
  const Twist fwd{1000, 0, 0};  // 100 mm/s forward
  uint32_t t = 0;
  Twist out = a.update(fwd, at(1500), t, cfg);
  EXPECT_EQ(a.state(), AvoidState::kForward);
  EXPECT_EQ(out.vx, 1000);
  // Slow-down band: 300 mm is half-way between 200 and 400 -> 62 %.
  out = a.update(fwd, at(300), t += 100, cfg);
  EXPECT_EQ(out.vx, 1000 * (25 + 75 * 100 / 200) / 100);
  // 19 cm: sidestep left at the forward speed.
  out = a.update(fwd, at(190), t += 100, cfg);
  EXPECT_EQ(a.state(), AvoidState::kSidestep);
  EXPECT_EQ(out.vx, 0);
  EXPECT_EQ(out.vy, 1000);
  // 22 cm is inside the hysteresis: keep going sideways.
  out = a.update(fwd, at(220), t += 100, cfg);
  EXPECT_EQ(a.state(), AvoidState::kSidestep);
  // Clear: a little more sideways for clear_hold_ms, then forward again.
  out = a.update(fwd, at(2000), t += 100, cfg);
  EXPECT_EQ(a.state(), AvoidState::kClearing);
  EXPECT_EQ(out.vy, 1000);
  out = a.update(fwd, at(2000), t += cfg.clear_hold_ms - 1, cfg);
  EXPECT_EQ(a.state(), AvoidState::kClearing);
  out = a.update(fwd, at(2000), t += 1, cfg);
  EXPECT_EQ(a.state(), AvoidState::kForward);
  EXPECT_EQ(out.vx, 1000);
  EXPECT_EQ(out.vy, 0);
}

// Avoidance walking forward at 100 mm/s with a 150 mm clearing distance,
// stepped in 20 ms ticks (kUnknown: no walked speed given).
struct ClearingRun {
  static constexpr int32_t kUnknown = strider::Avoidance::kUnknownSpeed;
  strider::Avoidance a;
  strider::AvoidConfig cfg = [] {
    auto c = strider::default_avoid_config();
    c.clear_mm = 150;
    return c;
  }();
  const Twist fwd{1000, 0, 0};
  uint32_t t = 0;

  Twist update(uint16_t mm, uint32_t dt_ms, int32_t walked_vy) {
    t += dt_ms;
    return walked_vy == kUnknown ? a.update(fwd, at(mm), t, cfg) : a.update(fwd, at(mm), t, cfg, walked_vy);
  }
  //! Obstacle, then clear: into the clearing state.
  void enter_clearing(int32_t walked_vy) {
    update(190, 20, walked_vy);
    ASSERT_EQ(a.state(), AvoidState::kSidestep);
    update(2000, 20, walked_vy);
    ASSERT_EQ(a.state(), AvoidState::kClearing);
  }
  //! How long clearing lasts [ms] walking sideways at walked_vy (at most 20 s).
  uint32_t clearing_ms(int32_t walked_vy) {
    const uint32_t start = t;
    while (a.state() == AvoidState::kClearing && t - start < 20000) {
      const Twist out = update(2000, 20, walked_vy);
      if (a.state() == AvoidState::kClearing) EXPECT_EQ(out.vy, 1000);
    }
    EXPECT_EQ(a.state(), AvoidState::kForward);
    return t - start;
  }
};

// The sensor's narrow beam sees the way clear before the body and its feet
// have passed the edge: clearing lasts until the body has walked clear_mm
// sideways at the speed it really walks (the gait's, not the command's).
TEST(Avoidance, ClearingWalksTheBodyHalfWidth) {
  ClearingRun r;
  r.enter_clearing(500);
  // Walking 50 mm/s sideways (either side counts): 150 mm take 3 s
  // (clear_hold_ms alone: 0.6 s).
  EXPECT_NEAR(double(r.clearing_ms(-500)), 3000.0, 20.0);
  // Unknown walked speed: the command's (100 mm/s) -> 1.5 s.
  r.enter_clearing(ClearingRun::kUnknown);
  EXPECT_NEAR(double(r.clearing_ms(ClearingRun::kUnknown)), 1500.0, 20.0);
}

// A gait that does not move sideways must not keep clearing for ever: the
// side timeout ends it.
TEST(Avoidance, ClearingEndsAtTheSideTimeoutWhenTheBodyDoesNotMove) {
  ClearingRun r;
  r.enter_clearing(0);
  EXPECT_NEAR(double(r.clearing_ms(0)), double(r.cfg.side_timeout_ms), 20.0);
  // Absurd speeds and clock jumps saturate, never wrap back into clearing.
  r.enter_clearing(0);
  r.update(2000, 4000000000u, -0x7FFFFFFF);
  EXPECT_EQ(r.a.state(), AvoidState::kForward);
}

TEST(Avoidance, OtherSideThenBlocked) {
  strider::Avoidance a;
  const auto cfg = strider::default_avoid_config();
  const Twist fwd{500, 0, 0};
  uint32_t t = 1000;
  a.update(fwd, at(100), t, cfg);
  EXPECT_EQ(a.side(), 1);
  Twist out = a.update(fwd, at(100), t += cfg.side_timeout_ms, cfg);
  EXPECT_EQ(a.side(), -1);  // left took too long: try right
  EXPECT_EQ(out.vy, -500);
  out = a.update(fwd, at(100), t += 2u * cfg.side_timeout_ms - 1, cfg);
  EXPECT_EQ(a.state(), AvoidState::kSidestep);
  out = a.update(fwd, at(100), t += 1, cfg);
  EXPECT_EQ(a.state(), AvoidState::kBlocked);
  EXPECT_EQ(out.vx, 0);
  EXPECT_EQ(out.vy, 0);
  // The operator backs off: pass-through, avoidance re-armed.
  out = a.update(Twist{-500, 0, 0}, at(100), t += 10, cfg);
  EXPECT_EQ(a.state(), AvoidState::kPassThrough);
  EXPECT_EQ(out.vx, -500);
}

TEST(Avoidance, OnlyWhileWalkingForwardAndEnabled) {
  strider::Avoidance a;
  auto cfg = strider::default_avoid_config();
  Twist out = a.update(Twist{0, 800, 0}, at(50), 0, cfg);  // sideways near a wall: allowed
  EXPECT_EQ(out.vy, 800);
  EXPECT_EQ(a.state(), AvoidState::kPassThrough);
  cfg.enabled = false;
  out = a.update(Twist{800, 0, 0}, at(50), 10, cfg);
  EXPECT_EQ(out.vx, 800);
}

TEST(Avoidance, SensorFailureRefusesForward) {
  strider::Avoidance a;
  const auto cfg = strider::default_avoid_config();
  for (SonarStatus st : {SonarStatus::kFailed, SonarStatus::kStale}) {
    Twist out = a.update(Twist{800, 100, 50}, SonarReading{st, strider::kSonarFarMm}, 0, cfg);
    EXPECT_EQ(a.state(), AvoidState::kSensorFault);
    EXPECT_EQ(out.vx, 0);
    EXPECT_EQ(out.vy, 100);
    EXPECT_EQ(out.wz, 50);
    out = a.update(Twist{-800, 0, 0}, SonarReading{st, strider::kSonarFarMm}, 10, cfg);
    EXPECT_EQ(out.vx, -800);  // backing away is still allowed
  }
}

TEST(Avoidance, RandomSequencesNeverWalkIntoObstacle) {
  std::mt19937 rng(4242u);
  std::uniform_int_distribution<int> dist(0, 3100);
  std::uniform_int_distribution<int> vx(-1000, 3000);
  std::uniform_int_distribution<int> st(0, 9);
  const auto cfg = strider::default_avoid_config();
  strider::Avoidance a;
  uint32_t t = 0;
  for (int i = 0; i < STRIDER_RANDOM_CASES * 10; ++i) {
    const int s = st(rng);
    const SonarReading r{s == 0 ? SonarStatus::kFailed : s == 1 ? SonarStatus::kNoData : SonarStatus::kOk,
                         uint16_t(dist(rng))};
    const Twist cmd{vx(rng), 0, 0};
    const Twist out = a.update(cmd, r, t += 20, cfg);
    if ((r.status == SonarStatus::kOk && r.distance_mm < cfg.stop_mm) || r.status == SonarStatus::kFailed) {
      ASSERT_LE(out.vx, 0);
    }
    ASSERT_LE(out.vx, cmd.vx > 0 ? cmd.vx : 0);
  }
}

TEST(Deadman, StopsOnlyWhenMovingAndSilent) {
  strider::Deadman d(1000);
  d.feed(0);
  EXPECT_FALSE(d.expired(999, true));
  EXPECT_TRUE(d.expired(1000, true));
  EXPECT_FALSE(d.expired(1500, true));  // reported once
  d.feed(2000);
  EXPECT_FALSE(d.expired(2500, true));
  EXPECT_TRUE(d.expired(3001, true));
  // Standing still needs no keep-alive.
  strider::Deadman idle(1000);
  EXPECT_FALSE(idle.expired(50000, false));
  EXPECT_FALSE(idle.expired(50500, true));  // the wait restarted when it began moving
  EXPECT_TRUE(idle.expired(51000, true));
  // Off.
  strider::Deadman off(0);
  EXPECT_FALSE(off.expired(100000, true));
  // Clock wrap.
  strider::Deadman w(500);
  w.feed(0xFFFFFF00u);
  EXPECT_FALSE(w.expired(0x000000F0u, true));
  EXPECT_TRUE(w.expired(0x00000200u, true));
}

}  // namespace
