// The two conversions every test typed over float and Fixed writes most:
// sc<S>(double) into the scalar under test, dbl(S) back for the double
// reference.
#ifndef STRIDER_TEST_SUPPORT_SCALAR_CONV_H
#define STRIDER_TEST_SUPPORT_SCALAR_CONV_H

#include "math/scalar.h"

namespace strider_test {

template <typename S>
S sc(double v) {
  return strider::scalar<S>(v);
}
template <typename S>
double dbl(S v) {
  return strider::to_double(v);
}

}  // namespace strider_test

#endif  // STRIDER_TEST_SUPPORT_SCALAR_CONV_H
