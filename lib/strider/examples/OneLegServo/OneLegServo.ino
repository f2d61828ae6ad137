// OneLegServo: one leg of the hexapod18 model (coxa, femur, tibia: three
// servos) moves its foot to and fro along a straight line, 40 mm long, through
// its standing position, one servo frame every 20 ms.
//
// Hardware: a PCA9685 servo board at I2C address 0x40 (SDA 20, SCL 21 on the
// Mega), the front left leg's coxa, femur and tibia servos on outputs 0, 1 and
// 2 (docs/wiring.md), a separate 5-6 V supply for the servos. Serial (115200
// baud) prints the joints once a second.
//
// Libraries: Strider, and Adafruit PWM Servo Driver Library (with its
// dependency Adafruit BusIO) from the Library Manager. Strider needs C++14:
// add compiler.cpp.extra_flags=-std=gnu++14 to a platform.local.txt beside the
// AVR core's platform.txt (docs/arduino.md).
//
// Per frame: IK of the foot target in fixed point (Fixed), each joint angle
// through the model's servo map (centre at the middle of the joint's range,
// direction, limits, pulse range of the servo part) to PCA9685 ticks, and one
// setPWM() per servo.

#include <Adafruit_PWMServoDriver.h>
#include <Wire.h>
#include <strider.h>

using namespace strider;

constexpr uint8_t kLeg = 0;               // front_left: joints 0, 1, 2 of the model
constexpr uint32_t kOscHz = 25000000ul;   // the board's oscillator (nominal; 23-27 MHz: calibrate it)
constexpr uint16_t kPwmHz = 50;           // servo frame rate
constexpr unsigned long kFrameUs = 20000ul;
constexpr int kHalfCycleFrames = 50;      // 1 s one way, 1 s back
constexpr float kLineHalfMm = 20.0f;      // the foot runs y = -20..+20 mm

// The leg and its servo channels, built from the model.
AnyLeg<Fixed> legSolver;
ServoChannel<Fixed> channels[3];
// The standing foot in the leg frame [mm] (x 120, y 0, z -90).
constexpr Vec3<float> kStand = body_point_in_leg(kHexapod18.legs[kLeg], kHexapod18.legs[kLeg].stand_mm);

Adafruit_PWMServoDriver pwm(kPcaFirstAddress, Wire);
Pca9685Timing timing;
unsigned long nextFrameUs;
int frame;

void setup() {
  Serial.begin(115200);
  AnyLeg<Fixed>::from_model(kHexapod18, kLeg, legSolver);
  for (uint8_t j = 0; j < 3; ++j) channels[j] = make_joint_channel<Fixed>(kHexapod18, kLeg, j);
  pwm.begin();
  // Strider computes the ticks from the oscillator (pca9685_timing.h); the
  // frequency given to the library brings back exactly Strider's prescale.
  timing.configure(kOscHz, kPwmHz);
  pwm.setOscillatorFrequency(kOscHz);
  pwm.setPWMFreq(float(kOscHz) / (4096.0f * (float(timing.prescale()) + 1.0f)));
  Wire.setClock(400000);
  nextFrameUs = micros();
}

void loop() {
  if (long(micros() - nextFrameUs) < 0) return;
  nextFrameUs += kFrameUs;

  // A triangle wave: -20 mm to +20 mm and back.
  frame = (frame + 1) % (2 * kHalfCycleFrames);
  const int k = frame < kHalfCycleFrames ? frame : 2 * kHalfCycleFrames - frame;
  const float y = -kLineHalfMm + 2.0f * kLineHalfMm * float(k) / float(kHalfCycleFrames);
  const Vec3<Fixed> target(Fixed(kStand.x), Fixed(y), Fixed(kStand.z));

  AnyLeg<Fixed>::Joints q;
  Vec3<Fixed> reached;
  const IkStatus status = legSolver.ik(target, q, reached);
  if (status == IkStatus::kUnreachable) return;  // keep the last pose

  uint16_t ticks[3];
  for (uint8_t j = 0; j < 3; ++j) {
    const ServoCommand cmd = map_joint(channels[j], q[j], Fixed(0), timing);
    ticks[j] = cmd.ticks;
    pwm.setPWM(cmd.channel % kPcaChannelsPerBoard, 0, cmd.ticks);
  }

  if (frame % kHalfCycleFrames == 0) {
    Serial.print(F("y "));
    Serial.print(y, 1);
    Serial.print(F(" mm, "));
    Serial.print(to_string(status));
    Serial.print(F(", joints [deg]"));
    for (uint8_t j = 0; j < 3; ++j) {
      Serial.print(' ');
      Serial.print(q[j].to_float() * float(kRadToDeg), 1);
    }
    Serial.print(F(", ticks"));
    for (uint8_t j = 0; j < 3; ++j) {
      Serial.print(' ');
      Serial.print(ticks[j]);
    }
    Serial.println();
  }
}
