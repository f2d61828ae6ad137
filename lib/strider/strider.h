//! Strider: kinematics and gaits for small hobby-servo legged robots.
//! The umbrella header; each header below also compiles on its own.
//! Header-only C++14, no heap, no standard library: the same code runs on an
//! ATmega2560 (avr-gcc, -std=gnu++14) and on the host.
#ifndef STRIDER_H
#define STRIDER_H

// The Arduino AVR core compiles C++ as gnu++11: say what to change rather
// than fail on the first C++14 constexpr function.
#if defined(__cplusplus) && __cplusplus < 201402L
#error "Strider needs C++14. Arduino IDE: add the line compiler.cpp.extra_flags=-std=gnu++14 to a platform.local.txt beside the AVR core's platform.txt (docs/arduino.md); PlatformIO: build_unflags = -std=gnu++11, build_flags = -std=gnu++14."
#else

// Arduino.h (included first in every sketch) defines min, max, abs, round,
// constrain, sq, radians and degrees as function-like macros that would rewrite the library's own
// names; they are set aside here and restored at the end.
#pragma push_macro("min")
#pragma push_macro("max")
#pragma push_macro("abs")
#pragma push_macro("round")
#pragma push_macro("constrain")
#pragma push_macro("sq")
#pragma push_macro("radians")
#pragma push_macro("degrees")
#undef min
#undef max
#undef abs
#undef round
#undef constrain
#undef sq
#undef radians
#undef degrees

// math: scalars (float, Fixed Q16.16), vectors, rotations, DH transforms
#include "math/scalar.h"
#include "math/vec3.h"
#include "math/mat3.h"
#include "math/transform.h"
#include "math/rotation.h"
#include "math/dh.h"
#include "math/prng.h"

// kinematics: leg types, mounts, body pose, generic chains, optimisers
#include "kinematics/ik_status.h"
#include "kinematics/joints.h"
#include "kinematics/sprawl_leg.h"
#include "kinematics/planar_leg.h"
#include "kinematics/coxa_femur_tibia_leg.h"
#include "kinematics/abduction_leg.h"
#include "kinematics/leg_mount.h"
#include "kinematics/body_pose.h"
#include "kinematics/dh_chain.h"
#include "kinematics/dls_ik.h"
#include "kinematics/pso.h"

// robots: the built-in models and a leg of any kind built from one
#include "robots/all_robots.h"
#include "kinematics/any_leg.h"

// gait: gait tables, phase, swing/stance trajectories, engine, walker, stability
#include "gait/gait.h"

// control: command protocol, servo map, settings, sonar, avoidance, controller
#include "control/command_parser.h"
#include "control/line_check.h"
#include "control/reply.h"
#include "control/servo_map.h"
#include "control/pca9685_timing.h"
#include "control/settings_store.h"
#include "control/calibration.h"
#include "control/sonar_filter.h"
#include "control/avoidance.h"
#include "control/deadman.h"
#include "control/controller.h"
#include "control/channel_map.h"
#include "control/walker_motion.h"
#include "control/servo_stage.h"
#include "control/robot_app.h"

// sensing: IMU samples, MPU-6050 register words, gyro offset, roll and pitch
#include "sensing/imu_sample.h"
#include "sensing/mpu6050_sample.h"
#include "sensing/gyro_calibration.h"
#include "sensing/attitude_filter.h"

#pragma pop_macro("degrees")
#pragma pop_macro("radians")
#pragma pop_macro("sq")
#pragma pop_macro("constrain")
#pragma pop_macro("round")
#pragma pop_macro("abs")
#pragma pop_macro("max")
#pragma pop_macro("min")

#endif  // C++14
#endif  // STRIDER_H
