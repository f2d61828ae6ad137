// Random DH chains for the chain tests: the same chain in scalar S and in
// double (built from the values S actually holds).
#ifndef STRIDER_TEST_CHAIN_RANDOM_H
#define STRIDER_TEST_CHAIN_RANDOM_H

#include <random>
#include <vector>

#include "chain_reference.h"
#include "kinematics/dh_chain.h"

namespace chain_test {

template <typename S, uint8_t N>
struct RandomChain {
  strider::DhChain<S, N> chain;
  RefChain ref;
};

// Links of a robot-sized arm: a in [5, 80] mm, d in [-40, 40] mm, any twist
// and offset; a base with any rotation and up to 100 mm of translation when
// with_base is set.
template <typename S, uint8_t N>
RandomChain<S, N> random_chain(std::mt19937& rng, bool with_base) {
  std::uniform_real_distribution<double> ang(-3.14159, 3.14159), a(5.0, 80.0), d(-40.0, 40.0), t(-100.0, 100.0);
  strider::DhParams<S> links[N];
  RandomChain<S, N> out;
  for (uint8_t i = 0; i < N; ++i) {
    links[i] = strider::DhParams<S>{strider::scalar<S>(a(rng)), strider::scalar<S>(ang(rng)),
                                    strider::scalar<S>(d(rng)), strider::scalar<S>(ang(rng))};
    out.ref.links.push_back(strider::DhParams<double>{dbl(links[i].a_mm), dbl(links[i].alpha_rad), dbl(links[i].d_mm),
                                                      dbl(links[i].theta_offset_rad)});
  }
  strider::Transform<S> base = strider::Transform<S>::identity();
  if (with_base) {
    base.rotation = strider::rotation_rpy(strider::scalar<S>(ang(rng)), strider::scalar<S>(ang(rng) / 2),
                                          strider::scalar<S>(ang(rng)));
    base.translation = strider::Vec3<S>(strider::scalar<S>(t(rng)), strider::scalar<S>(t(rng)), strider::scalar<S>(t(rng)));
  }
  out.chain = strider::DhChain<S, N>(links, strider::JointLimits<S, N>::unlimited(), base);
  out.ref.base = to_eigen(base);
  return out;
}

template <typename S, uint8_t N>
strider::JointVector<S, N> random_joints(std::mt19937& rng, double lo = -3.14159, double hi = 3.14159) {
  std::uniform_real_distribution<double> ang(lo, hi);
  strider::JointVector<S, N> q;
  for (uint8_t i = 0; i < N; ++i) q[i] = strider::scalar<S>(ang(rng));
  return q;
}

template <typename S, uint8_t N>
std::vector<double> to_vector(const strider::JointVector<S, N>& q) {
  std::vector<double> v;
  for (uint8_t i = 0; i < N; ++i) v.push_back(dbl(q[i]));
  return v;
}

}  // namespace chain_test

#endif  // STRIDER_TEST_CHAIN_RANDOM_H
