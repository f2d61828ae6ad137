//! ZeroedStorage: a constructor tag for an object built in place in storage
//! that holds only zero bytes (a global array in .bss that nothing has
//! written yet). Such a constructor writes only the members whose default is
//! not zero; the object then equals, byte for byte, one that the default
//! constructor built in zeroed storage (test/control/test_zeroed_storage.cpp
//! compares them for every model, float and Fixed). Objects anywhere else
//! (the stack, the heap, a global already used) take the default constructor.
//!
//! Why: Fixed's default constructor stores its zero, and a class's default
//! constructor stores every such member one by one; the AVR spends 2 to 6
//! bytes of code per byte stored, and avr-gcc 5 does not drop stores that a
//! memset before them makes redundant.
//!
//! A float member named with the tag (`x_(z)`) is stored as 0 (the
//! conversion below): one constructor serves both scalars; members without
//! a default of their own that the tag constructor leaves out (integers,
//! flags, arrays in anonymous unions, a Vec3) cost nothing in either.
//!
//! gcc 6 and later take an object's storage as indeterminate when its
//! constructor starts (-flifetime-dse=2): code built with such a constructor
//! needs -fno-lifetime-dse (or -flifetime-dse=1), as the firmware
//! (src/CMakeLists.txt, platformio.ini) and its test have; gcc 5 does not
//! assume it.
#ifndef STRIDER_MATH_ZEROED_STORAGE_H
#define STRIDER_MATH_ZEROED_STORAGE_H

namespace strider {

struct ZeroedStorage {
  constexpr operator float() const { return 0.0f; }
};
constexpr ZeroedStorage kZeroedStorage{};

class Fixed;
//! Which scalar a class template's tag constructor is for (an overload
//! tag): Vec3 names its Fixed members with the tag and leaves float ones
//! out, so that neither stores.
template <typename S>
struct ZeroedFor {};

}  // namespace strider

#endif  // STRIDER_MATH_ZEROED_STORAGE_H
