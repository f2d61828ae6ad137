// Checks the analytic leg tests share, over any leg type and scalar: a
// Cartesian sweep against a double reference IK, one row of an edge table,
// and non-finite targets. Built on leg_test_util.h.
#ifndef STRIDER_TEST_SUPPORT_LEG_TEST_SUPPORT_H
#define STRIDER_TEST_SUPPORT_LEG_TEST_SUPPORT_H

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "leg_test_util.h"

namespace legtest {

//! How much of the reference's answer a sweep target is compared with: near a
//! tie between two solutions only the status is, near a singular boundary the
//! status and the reached point, elsewhere also the joints.
enum class Compare { kStatus, kFoot, kFootAndJoints };

//! A sweep of targets against a double reference IK: each target's status
//! against the one the reference's miss gives, the reached point against the
//! reference's nearest reachable point, the joints against the reference's;
//! at the end the worst errors against Bounds<S> and how many targets gave
//! each status (so the sweep is known to cover all three). A wrong status is
//! counted and the first one named at the end, as RoundTrip does, so one bad
//! region does not print a failure per target.
template <typename S>
class ReferenceSweep {
 public:
  ReferenceSweep(const std::string& joint_name, const std::string& foot_name) : joint_(joint_name), foot_(foot_name) {}

  struct Solved {
    IkStatus status;
    Vec3<S> reached;
  };

  //! Solves the (quantised) target p. want is the reference's status
  //! (kJointLimit: too close to a threshold to call, not checked), miss its
  //! distance to the workspace [mm] for the message, nearest and q_ref (kDof
  //! angles [rad]) its answer, compared as far as `compare` says when p is
  //! reachable.
  template <template <typename> class LegT>
  Solved check(const LegT<S>& leg, const Eigen::Vector3d& p, IkStatus want, double miss,
               const Eigen::Vector3d& nearest, const double* q_ref, Compare compare) {
    typename LegT<S>::Joints q;
    Solved got;
    got.status = checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, got.reached);
    ++statuses_[uint8_t(got.status)];
    if (want != IkStatus::kJointLimit && got.status != want && bad_status_++ == 0) {
      std::ostringstream os;
      os << describe(p) << " status " << strider::to_string(got.status) << ", want " << strider::to_string(want)
         << ", miss " << miss;
      first_bad_ = os.str();
    }
    if (got.status == IkStatus::kUnreachable || compare == Compare::kStatus) return got;
    foot_.add((ev(got.reached) - nearest).norm(), [&] { return describe(p); });
    if (compare != Compare::kFootAndJoints) return got;
    double e = 0.0;
    for (uint8_t j = 0; j < LegT<S>::kDof; ++j) e = std::max(e, angle_diff(dbl(q[j]), q_ref[j]));
    joint_.add(e / kDeg, [&] { return describe(p); });
    return got;
  }

  //! Every status as the reference says, more than min_* targets kOk,
  //! kClamped and kUnreachable, and the worst errors within Bounds<S>.
  void expect_results(long min_ok, long min_clamped, long min_unreachable) const {
    EXPECT_EQ(bad_status_, 0) << "first at " << first_bad_;
    EXPECT_GT(statuses_[uint8_t(IkStatus::kOk)], min_ok);
    EXPECT_GT(statuses_[uint8_t(IkStatus::kClamped)], min_clamped);
    EXPECT_GT(statuses_[uint8_t(IkStatus::kUnreachable)], min_unreachable);
    EXPECT_LE(joint_.max(), Bounds<S>::kJointDeg) << joint_.where();
    EXPECT_LE(foot_.max(), Bounds<S>::kFootMm) << foot_.where();
  }

 private:
  Worst joint_, foot_;
  long statuses_[4] = {0, 0, 0, 0};
  long bad_status_ = 0;
  std::string first_bad_;
};

//! One row of an edge table: a target, the status it gives, and the distance
//! from it to the reached point [mm] (< 0: not checked).
struct EdgeRow {
  const char* what;
  double x, y, z;
  IkStatus want;
  double miss;
};

//! Checks one edge-table row (anything with EdgeRow's fields) on leg and
//! returns the joints for checks of the leg's own.
template <template <typename> class LegT, typename S, typename Row>
typename LegT<S>::Joints expect_edge_row(const LegT<S>& leg, const Row& c) {
  typename LegT<S>::Joints q;
  Vec3<S> reached;
  const Vec3<S> target = vec<S>(c.x, c.y, c.z);
  EXPECT_EQ(checked_ik(leg, target, q, reached), c.want) << c.what;
  if (c.miss >= 0) {
    EXPECT_NEAR((ev(reached) - ev(target)).norm(), c.miss, Bounds<S>::kFootMm) << c.what;
  }
  return q;
}

//! NaN, +inf and -inf on each axis of an otherwise reachable target are
//! kUnreachable and leave the outputs untouched (checked_ik). Float only:
//! Fixed has no non-finite values.
template <typename Leg>
void expect_non_finite_targets_unreachable(const Leg& leg, const Vec3<float>& reachable) {
  for (float b : {float(NAN), float(INFINITY), -float(INFINITY)})
    for (int axis = 0; axis < 3; ++axis) {
      Vec3<float> t = reachable;
      (axis == 0 ? t.x : axis == 1 ? t.y : t.z) = b;
      typename Leg::Joints q;
      Vec3<float> reached;
      EXPECT_EQ(checked_ik(leg, t, q, reached), IkStatus::kUnreachable) << b << " on axis " << axis;
    }
}

}  // namespace legtest

#endif  // STRIDER_TEST_SUPPORT_LEG_TEST_SUPPORT_H
