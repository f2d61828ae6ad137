//! constant_given<T, P>(): whether an optional compile-time constant was
//! given, for a template parameter P of pointer type T whose default nullptr
//! means "build it at run time" (ServoStage's kChannels, RobotApp's
//! kStoredConfig, kStoredLegs, kStoredGait).
//!
//! Decided by the identity of two template arguments, not by comparing the
//! address with nullptr: g++ 12 does not accept `&x != nullptr` as a
//! constant expression for a variable template's instance when null pointer
//! checks are kept (-fno-delete-null-pointer-checks, which -fsanitize=undefined
//! implies), and avr-gcc warns about such a comparison (-Waddress).
#ifndef STRIDER_CONTROL_CONSTANT_GIVEN_H
#define STRIDER_CONTROL_CONSTANT_GIVEN_H

namespace strider {
namespace constant_given_detail {

template <typename T, T P>
struct Arg {};
template <typename A, typename B>
struct Same {
  static constexpr bool value = false;
};
template <typename A>
struct Same<A, A> {
  static constexpr bool value = true;
};

}  // namespace constant_given_detail

//! True when P (of pointer type T) is not nullptr.
template <typename T, T P>
constexpr bool constant_given() {
  return !constant_given_detail::Same<constant_given_detail::Arg<T, P>, constant_given_detail::Arg<T, nullptr>>::value;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_CONSTANT_GIVEN_H
