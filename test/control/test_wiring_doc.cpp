// docs/wiring.md's channel tables are the channel map of the code: this test
// renders the tables from lib/strider/control/channel_map.h and compares.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "control/channel_map.h"
#include "robots/all_robots.h"

namespace {

std::string render_tables() {
  std::string out;
  char line[256];
  for (const strider::RobotModel* m : strider::kAllRobots) {
    out += "\n### " + std::string(m->name) +
           "\n\n| leg | joint | board | pin | direction | servo centre at joint [deg] | range [deg] |\n"
           "|---|---|---|---|---|---|---|\n";
    for (int i = 0; i < m->leg_count; ++i)
      for (int j = 0; j < m->dof(); ++j) {
        const auto c = strider::make_joint_channel<float>(*m, uint8_t(i), uint8_t(j));
        const auto& r = m->legs[i].joint[j];
        std::snprintf(line, sizeof line, "| %d %s | %d | 0x%02X | %d | %+d | %.1f | %.0f .. %.0f |\n", i,
                      m->legs[i].name, j, 0x40 + c.channel / 16, c.channel % 16, c.direction,
                      double(c.zero_rad) * 57.29577951308232, double(r.min_deg), double(r.max_deg));
        out += line;
      }
  }
  return out;
}

TEST(WiringDoc, ChannelTablesMatchTheCode) {
  std::ifstream f(STRIDER_WIRING_DOC);
  ASSERT_TRUE(f) << STRIDER_WIRING_DOC;
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string doc = ss.str();
  const std::string begin = "<!-- channels:begin -->\n", end = "<!-- channels:end -->";
  const size_t b = doc.find(begin), e = doc.find(end);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  auto trimmed = [](std::string t) {
    while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
    return t;
  };
  const std::string tables = doc.substr(b + begin.size(), e - b - begin.size());
  EXPECT_EQ(trimmed(tables), trimmed(render_tables())) << "paste this between the markers:\n" << render_tables();
}

TEST(ChannelMap, EveryModelFitsItsBoardsWithoutSharing) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    strider::ServoChannel<float> ch[strider::kMaxServoJoints];
    ASSERT_EQ(strider::make_channel_map<float>(*m, ch), m->joint_count()) << m->name;
    bool used[32] = {};
    for (int k = 0; k < m->joint_count(); ++k) {
      ASSERT_LT(ch[k].channel, 16 * strider::pca_board_count(*m)) << m->name;
      EXPECT_FALSE(used[ch[k].channel]) << m->name << " channel " << int(ch[k].channel);
      used[ch[k].channel] = true;
      // The joint range maps inside the servo's travel, centred.
      const double lo = strider::joint_from_pulse(ch[k], 500.0), hi = strider::joint_from_pulse(ch[k], 2500.0);
      const auto& r = m->legs[k / m->dof()].joint[k % m->dof()];
      EXPECT_LE(std::min(lo, hi), r.min_deg * strider::kDegToRad + 1e-6) << m->name;
      EXPECT_GE(std::max(lo, hi), r.max_deg * strider::kDegToRad - 1e-6) << m->name;
      EXPECT_NEAR(strider::joint_from_pulse(ch[k], 1500.0), double(ch[k].zero_rad), 1e-6);
    }
  }
}

// joint -> pulse (servo_map.h) -> joint (joint_from_pulse) is the identity
// within a microsecond's worth of angle, for every joint of every model.
TEST(ChannelMap, PulseRoundTrip) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    strider::ServoChannel<float> ch[strider::kMaxServoJoints];
    strider::make_channel_map<float>(*m, ch);
    for (int k = 0; k < m->joint_count(); ++k) {
      const auto& r = m->legs[k / m->dof()].joint[k % m->dof()];
      for (double deg = r.min_deg + 0.01; deg <= r.max_deg - 0.01; deg += 7.0) {
        float servo = 0;
        ASSERT_EQ(strider::servo_angle(ch[k], float(deg * strider::kDegToRad), 0.0f, &servo), strider::ServoStatus::kOk);
        const uint16_t us = strider::servo_pulse_us(ch[k], servo);
        const double back = strider::joint_from_pulse(ch[k], us);
        EXPECT_NEAR(back, deg * strider::kDegToRad, 0.5 / double(ch[k].us_per_rad) + 1e-6) << m->name << " " << k;
      }
    }
  }
}

}  // namespace
