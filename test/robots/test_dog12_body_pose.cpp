// Seed 001's extreme body poses on dog12: table 4's roll -28..28 deg, pitch
// -21..21 deg and yaw -21..21 deg in 1 deg steps, one axis at a time, and the
// eight corners with all three at their extremes. The feet stay at the
// standing pose on the ground; every leg must solve with status ok, and the
// joints must put the foot where the rotated body needs it.
#include <gtest/gtest.h>

#include <vector>

#include "kinematics/body_pose.h"
#include "robot_reference.h"

using namespace strider;
using robot_ref::Vector3d;

namespace {

struct PoseDeg {
  double roll, pitch, yaw;
};

// Seed 001 table 4 ranges.
constexpr int kRollDeg = 28;
constexpr int kPitchDeg = 21;
constexpr int kYawDeg = 21;

std::vector<PoseDeg> seed001_poses() {
  std::vector<PoseDeg> out;
  for (int r = -kRollDeg; r <= kRollDeg; ++r) out.push_back({double(r), 0, 0});
  for (int p = -kPitchDeg; p <= kPitchDeg; ++p) out.push_back({0, double(p), 0});
  for (int y = -kYawDeg; y <= kYawDeg; ++y) out.push_back({0, 0, double(y)});
  for (int sr : {-1, 1})
    for (int sp : {-1, 1})
      for (int sy : {-1, 1}) out.push_back({sr * double(kRollDeg), sp * double(kPitchDeg), sy * double(kYawDeg)});
  return out;
}

template <typename S>
class Dog12BodyPose : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(Dog12BodyPose, Scalars);

TYPED_TEST(Dog12BodyPose, Seed001Table4PosesSolveOk) {
  using S = TypeParam;
  const RobotModel& m = kDog12;
  AnyLeg<S> legs[4];
  for (uint8_t i = 0; i < 4; ++i) ASSERT_TRUE(AnyLeg<S>::from_model(m, i, legs[i]));
  double worst_mm = 0.0;
  int solved = 0;
  for (const PoseDeg& pd : seed001_poses()) {
    const BodyPose<S> pose = BodyPose<S>::make(Vec3<S>(), deg_to_rad<S>(pd.roll), deg_to_rad<S>(pd.pitch),
                                               deg_to_rad<S>(pd.yaw));
    const Transform<S> body = body_transform(pose);
    // Double reference of the moved foot: R = Rz(yaw) Ry(pitch) Rx(roll)
    // (kZYX, seed 001's default), foot' = R^T p.
    const Eigen::Matrix3d r =
        (Eigen::AngleAxisd(robot_ref::rad(pd.yaw), Vector3d::UnitZ()) *
         Eigen::AngleAxisd(robot_ref::rad(pd.pitch), Vector3d::UnitY()) *
         Eigen::AngleAxisd(robot_ref::rad(pd.roll), Vector3d::UnitX()))
            .matrix();
    for (uint8_t i = 0; i < 4; ++i) {
      const LegModel& lm = m.legs[i];
      const Vec3<S> foot = foot_in_body(body, Vec3<S>::from(lm.stand_mm));
      typename AnyLeg<S>::Joints q{};
      Vec3<S> reached;
      const IkStatus s = legs[i].ik_body(foot, q, reached);
      ASSERT_EQ(s, IkStatus::kOk) << "leg " << int(i) << " roll " << pd.roll << " pitch " << pd.pitch << " yaw "
                                  << pd.yaw;
      const Vector3d want = r.transpose() * Vector3d(lm.stand_mm.x, lm.stand_mm.y, lm.stand_mm.z);
      const double qd[3] = {to_double(q[0]), to_double(q[1]), to_double(q[2])};
      const double err = (robot_ref::body_fk(m, lm, qd) - want).norm();
      worst_mm = std::max(worst_mm, err);
      EXPECT_LT(err, robot_ref::Bounds<S>::kPositionMm) << "leg " << int(i);
      ++solved;
    }
  }
  EXPECT_EQ(solved, 4 * (57 + 43 + 43 + 8));
  std::printf("[ measured ] dog12 seed 001 poses, %s: %d leg solutions, worst foot error %.2e mm\n",
              ScalarTraits<S>::name(), solved, worst_mm);
}

// Past the table's ranges the model's limits or reach must show: at a 60 deg
// roll (either way) some leg can no longer solve with status ok.
TYPED_TEST(Dog12BodyPose, BeyondTheTableIsNotOk) {
  using S = TypeParam;
  for (double roll : {-60.0, 60.0}) {
    const Transform<S> body = body_transform(BodyPose<S>::make(Vec3<S>(), deg_to_rad<S>(roll), S(0), S(0)));
    int ok = 0;
    for (uint8_t i = 0; i < 4; ++i) {
      AnyLeg<S> leg;
      ASSERT_TRUE(AnyLeg<S>::from_model(kDog12, i, leg));
      typename AnyLeg<S>::Joints q{};
      Vec3<S> reached;
      if (leg.ik_body(foot_in_body(body, Vec3<S>::from(kDog12.legs[i].stand_mm)), q, reached) == IkStatus::kOk) ++ok;
    }
    EXPECT_LT(ok, 4) << "roll " << roll;
  }
}

}  // namespace
