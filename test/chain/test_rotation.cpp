// Rotation matrices (seed 001 eqs 5.1-5.3) and the six Tait-Bryan orders
// (seed 001 algorithm 2) against an Eigen double reference.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "chain_reference.h"
#include "math/rotation.h"

namespace {

using namespace chain_test;
using strider::Mat3;
using strider::RotationOrder;

template <typename S>
class RotationTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(RotationTyped, Scalars);

TYPED_TEST(RotationTyped, ElementaryMatricesAreSeedEqs51To53) {
  using S = TypeParam;
  const double b = Bounds<S>::kRotEntry;
  for (double a : {-2.5, -0.7, 0.0, 0.3, 1.2, 3.0}) {
    const S s = strider::scalar<S>(a);
    const double c = std::cos(dbl(s)), n = std::sin(dbl(s));
    Eigen::Matrix3d ex, ey, ez;
    ex << 1, 0, 0, 0, c, -n, 0, n, c;   // eq 5.1
    ey << c, 0, n, 0, 1, 0, -n, 0, c;   // eq 5.2
    ez << c, -n, 0, n, c, 0, 0, 0, 1;   // eq 5.3
    EXPECT_LE(max_abs_diff(to_eigen(strider::rot_x(s)), ex), b) << a;
    EXPECT_LE(max_abs_diff(to_eigen(strider::rot_y(s)), ey), b) << a;
    EXPECT_LE(max_abs_diff(to_eigen(strider::rot_z(s)), ez), b) << a;
  }
}

TYPED_TEST(RotationTyped, QuarterTurnsAreRightHanded) {
  using S = TypeParam;
  const S q = strider::half_pi<S>();
  const strider::Vec3<S> ex(S(1), S(0), S(0)), ey(S(0), S(1), S(0)), ez(S(0), S(0), S(1));
  const double b = Bounds<S>::kRotEntry;
  EXPECT_LE((to_eigen(strider::rot_x(q) * ey) - Eigen::Vector3d::UnitZ()).norm(), 2 * b);
  EXPECT_LE((to_eigen(strider::rot_y(q) * ez) - Eigen::Vector3d::UnitX()).norm(), 2 * b);
  EXPECT_LE((to_eigen(strider::rot_z(q) * ex) - Eigen::Vector3d::UnitY()).norm(), 2 * b);
}

TYPED_TEST(RotationTyped, SixOrdersMatchEigenOnRandomAngles) {
  using S = TypeParam;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> ang(-3.14159, 3.14159);
  double worst = 0.0;
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    const S r = strider::scalar<S>(ang(rng)), p = strider::scalar<S>(ang(rng)), y = strider::scalar<S>(ang(rng));
    for (RotationOrder o : kAllOrders) {
      const Eigen::Matrix3d ref = rpy_reference(dbl(r), dbl(p), dbl(y), o);
      const double e = max_abs_diff(to_eigen(strider::rotation_rpy(r, p, y, o)), ref);
      worst = std::max(worst, e);
      ASSERT_LE(e, Bounds<S>::kRotEntry) << strider::to_string(o) << " case " << i;
    }
  }
  ::testing::Test::RecordProperty("worst_entry_error", std::to_string(worst));
}

TYPED_TEST(RotationTyped, ResultIsOrthonormalWithDeterminantOne) {
  using S = TypeParam;
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> ang(-3.14159, 3.14159);
  for (int i = 0; i < STRIDER_RANDOM_CASES / 4; ++i) {
    for (RotationOrder o : kAllOrders) {
      const Eigen::Matrix3d m = to_eigen(strider::rotation_rpy(strider::scalar<S>(ang(rng)), strider::scalar<S>(ang(rng)),
                                                                 strider::scalar<S>(ang(rng)), o));
      ASSERT_LE(max_abs_diff(m * m.transpose(), Eigen::Matrix3d::Identity()), 4 * Bounds<S>::kRotEntry);
      ASSERT_NEAR(m.determinant(), 1.0, 6 * Bounds<S>::kRotEntry);
    }
  }
}

TYPED_TEST(RotationTyped, ZeroAnglesGiveIdentityInEveryOrder) {
  using S = TypeParam;
  for (RotationOrder o : kAllOrders) {
    const Mat3<S> m = strider::rotation_rpy(S(0), S(0), S(0), o);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_EQ(m.m[i][j], S(i == j ? 1 : 0));
  }
}

// Fixed composes the rotation column by column without the zero and unit
// terms: the bits must be those of the three elementary matrices multiplied
// with Mat3's product, left to right as the order names them.
TEST(RotationRpy, FixedIsTheMatrixProduct) {
  using strider::Fixed;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> ang(-3.3, 3.3);
  const double edges[] = {0.0, 1e-5, -1e-5, 1.5707963, -1.5707963, 3.1415926, -3.1415926, 0.7853982, 2.5};
  for (int i = 0; i < 4 * STRIDER_RANDOM_CASES + 729; ++i) {
    Fixed a[3];
    for (int k = 0; k < 3; ++k) {
      int e = i;
      for (int n = 0; n < k; ++n) e /= 9;
      a[k] = i < 729 ? Fixed(edges[e % 9]) : Fixed(ang(rng));
    }
    const Mat3<Fixed> x = strider::rot_x(a[0]), y = strider::rot_y(a[1]), z = strider::rot_z(a[2]);
    for (RotationOrder o : kAllOrders) {
      const Mat3<Fixed>* f[3] = {&z, &y, &x};
      switch (o) {
        case RotationOrder::kXYZ: f[0] = &x, f[1] = &y, f[2] = &z; break;
        case RotationOrder::kXZY: f[0] = &x, f[1] = &z, f[2] = &y; break;
        case RotationOrder::kYXZ: f[0] = &y, f[1] = &x, f[2] = &z; break;
        case RotationOrder::kYZX: f[0] = &y, f[1] = &z, f[2] = &x; break;
        case RotationOrder::kZXY: f[0] = &z, f[1] = &x, f[2] = &y; break;
        case RotationOrder::kZYX: break;
      }
      const Mat3<Fixed> want = *f[0] * *f[1] * *f[2];
      const Mat3<Fixed> got = strider::rotation_rpy(a[0], a[1], a[2], o);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(got.m[r][c].raw(), want.m[r][c].raw())
              << strider::to_string(o) << " case " << i << " entry " << r << c;
    }
  }
}

TEST(Rotation, DefaultOrderIsZyx) {
  const Mat3<float> a = strider::rotation_rpy(0.1f, -0.4f, 0.7f);
  const Mat3<float> b = strider::rotation_rpy(0.1f, -0.4f, 0.7f, RotationOrder::kZYX);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  // kZYX: Rz(yaw) Ry(pitch) Rx(roll); roll acts first on a vector.
  EXPECT_LE(max_abs_diff(to_eigen(a), rz(0.7) * ry(-0.4) * rx(0.1)), 2e-6);
}

// Seed 001 algorithm 2 keys its table by application order: each key is the
// Strider name reversed. Its five distinct entries (the listing repeats
// 'xzy' and writes 'yzy' for 'yzx') plus its missing default 'xyz'.
TEST(Rotation, SeedListingEntriesMapToStriderOrders) {
  const double r = 0.31, p = -0.52, y = 0.77;
  const Eigen::Matrix3d X = rx(r), Y = ry(p), Z = rz(y);
  struct Entry {
    const char* seed_key;
    Eigen::Matrix3d product;
    RotationOrder order;
  };
  const Entry entries[] = {
      {"xzy", Y * Z * X, RotationOrder::kYZX},  // listing lines 6-7
      {"yxz", Z * X * Y, RotationOrder::kZXY},  // line 8
      {"yzx", X * Z * Y, RotationOrder::kXZY},  // line 9, printed 'yzy'
      {"zxy", Y * X * Z, RotationOrder::kYXZ},  // line 10, printed 'xzy'
      {"zyx", X * Y * Z, RotationOrder::kXYZ},  // line 11
      {"xyz", Z * Y * X, RotationOrder::kZYX},  // the default, absent from the table
  };
  for (const Entry& e : entries) {
    const std::string key(e.seed_key);
    const std::string reversed(key.rbegin(), key.rend());
    EXPECT_EQ(reversed, strider::to_string(e.order));
    EXPECT_LE(max_abs_diff(to_eigen(strider::rotation_rpy(float(r), float(p), float(y), e.order)), e.product), 2e-6)
        << e.seed_key;
  }
}

TEST(Rotation, OrdersAreDistinct) {
  for (RotationOrder a : kAllOrders) {
    for (RotationOrder b : kAllOrders) {
      if (a == b) continue;
      EXPECT_GT(max_abs_diff(to_eigen(strider::rotation_rpy(0.3f, 0.5f, 0.7f, a)),
                             to_eigen(strider::rotation_rpy(0.3f, 0.5f, 0.7f, b))),
                1e-2);
    }
  }
}

TEST(Rotation, NamesRoundTripAndRejectOthers) {
  for (RotationOrder o : kAllOrders) {
    RotationOrder parsed = RotationOrder::kXYZ;
    ASSERT_TRUE(strider::parse_rotation_order(strider::to_string(o), parsed));
    EXPECT_EQ(parsed, o);
  }
  RotationOrder keep = RotationOrder::kYXZ;
  for (const char* bad : {"yzy", "xy", "", "xyzz", "XYZ", "xxz"}) {
    EXPECT_FALSE(strider::parse_rotation_order(bad, keep)) << bad;
    EXPECT_EQ(keep, RotationOrder::kYXZ);
  }
  EXPECT_FALSE(strider::parse_rotation_order(nullptr, keep));
}

}  // namespace
