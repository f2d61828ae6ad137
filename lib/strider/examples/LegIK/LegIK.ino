// LegIK: inverse kinematics of one 3-DOF coxa-femur-tibia leg, in float and
// in fixed point (strider::Fixed, Q16.16), printed over Serial (115200 baud)
// with the time each solve took. Needs nothing but the board.
//
// The leg is the hexapod18 model's: the femur axis 32 mm above the leg
// frame's origin, coxa 30 mm, femur 85 mm, tibia 125 mm. Leg frame: origin on
// the coxa (yaw) axis, x out along the leg, y to its left, z up. Joints [deg]:
// t1 coxa yaw, t2 femur pitch, t3 tibia pitch (positive upward; all zero is
// the leg stretched out level).
//
// Strider needs C++14: add compiler.cpp.extra_flags=-std=gnu++14 to a
// platform.local.txt beside the AVR core's platform.txt (docs/arduino.md).
#include <strider.h>

using namespace strider;

// Joint limits that never bind: every solve is the pure geometry.
const CoxaFemurTibiaLeg<float> kLegFloat = CoxaFemurTibiaLeg<float>::make(
    32.0f, 30.0f, 85.0f, 125.0f, JointLimits<float, 3>::unlimited());
const CoxaFemurTibiaLeg<Fixed> kLegFixed = CoxaFemurTibiaLeg<Fixed>::make(
    Fixed(32), Fixed(30), Fixed(85), Fixed(125), JointLimits<Fixed, 3>::unlimited());

// Feet to reach, leg frame [mm]: standing, forward and up, back and down, and
// one 100 mm beyond reach (the solvers say "unreachable" and write nothing).
const float kTargets[][3] = {
    {120.0f, 0.0f, -90.0f},
    {140.0f, 30.0f, -60.0f},
    {100.0f, -40.0f, -110.0f},
    {350.0f, 0.0f, 0.0f},
};

void printRow(const char* scalar, float x, float y, float z, IkStatus status, float t1, float t2, float t3,
              unsigned long us) {
  Serial.print(scalar);
  Serial.print(F(" foot ("));
  Serial.print(x, 0);
  Serial.print(F(", "));
  Serial.print(y, 0);
  Serial.print(F(", "));
  Serial.print(z, 0);
  Serial.print(F(") mm: "));
  Serial.print(to_string(status));
  if (status != IkStatus::kUnreachable) {
    Serial.print(F(", t1 "));
    Serial.print(t1, 2);
    Serial.print(F(" t2 "));
    Serial.print(t2, 2);
    Serial.print(F(" t3 "));
    Serial.print(t3, 2);
    Serial.print(F(" deg"));
  }
  Serial.print(F(", "));
  Serial.print(us);
  Serial.println(F(" us"));
}

void setup() {
  Serial.begin(115200);
  const float toDeg = float(kRadToDeg);
  for (const float* p : kTargets) {
    // float
    CoxaFemurTibiaLeg<float>::Joints qf = {};
    Vec3<float> reachedFloat;
    unsigned long t0 = micros();
    const IkStatus sf = kLegFloat.ik(Vec3<float>(p[0], p[1], p[2]), qf, reachedFloat);
    unsigned long us = micros() - t0;
    printRow("float", p[0], p[1], p[2], sf, qf[0] * toDeg, qf[1] * toDeg, qf[2] * toDeg, us);

    // fixed point: the same call with Fixed in place of float
    CoxaFemurTibiaLeg<Fixed>::Joints qx = {};
    Vec3<Fixed> reachedFixed;
    const Vec3<Fixed> target{Fixed(p[0]), Fixed(p[1]), Fixed(p[2])};
    t0 = micros();
    const IkStatus sx = kLegFixed.ik(target, qx, reachedFixed);
    us = micros() - t0;
    printRow("Fixed", p[0], p[1], p[2], sx, qx[0].to_float() * toDeg, qx[1].to_float() * toDeg,
             qx[2].to_float() * toDeg, us);

    // forward kinematics of the fixed-point joints: back to the foot
    if (sx != IkStatus::kUnreachable) {
      const Vec3<Fixed> foot = kLegFixed.fk(qx);
      Serial.print(F("  fk(Fixed joints) = ("));
      Serial.print(foot.x.to_float(), 2);
      Serial.print(F(", "));
      Serial.print(foot.y.to_float(), 2);
      Serial.print(F(", "));
      Serial.print(foot.z.to_float(), 2);
      Serial.println(F(") mm"));
    }
  }
}

void loop() {}
