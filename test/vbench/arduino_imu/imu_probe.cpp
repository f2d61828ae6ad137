// The IMU probe: the real Adafruit_MPU6050 library on the virtual Mega,
// answering one-letter commands on Serial (USB, 115200 baud) or Serial1 (the
// HC-05's port, 9600 baud; strider-sim's link) on the port they came from,
// so that a test can feed vbench's MPU-6050 and compare:
//   r        `event ax ay az gx gy gz t` from getEvent() [m/s^2, rad/s, deg C]
//   b        `burst` + the 14 data bytes read with Adafruit BusIO, then
//            `strider` + the same converted by strider::mpu6050_sample<Fixed>
//   aN / gN  accel range N (0..3: 2/4/8/16 g) / gyro range N (250..2000 deg/s)
//   v        `adc` + analogRead(A0..A7)
//   f        100 updates of strider::AttitudeFilter<float> (getEvent) and
//            <Fixed> (the burst, mpu6050_sample) 20 ms apart: `filter` roll
//            pitch [deg] of each, and the microseconds of one update of each
// At power-up it prints `begin ok` or `begin failed` (no MPU-6050 answers).
// Strider's headers come before Arduino.h, whose abs/min/max macros would
// rewrite them (strider.h sets the macros aside itself).
#include "sensing/attitude_filter.h"
#include "sensing/mpu6050_sample.h"

#include <Adafruit_MPU6050.h>
#include <Arduino.h>
#include <Wire.h>

namespace {

Adafruit_MPU6050 g_mpu;
// The raw burst through a BusIO device of our own (the library's is
// protected, and the class final).
Adafruit_I2CDevice g_raw(MPU6050_I2CADDR_DEFAULT, &Wire);

bool read_burst(uint8_t* bytes) {
  Adafruit_BusIO_Register data(&g_raw, MPU6050_ACCEL_OUT, strider::kMpu6050BurstBytes);
  return data.read(bytes, strider::kMpu6050BurstBytes);
}

bool g_ok = false;
strider::Mpu6050AccelRange g_accel = strider::Mpu6050AccelRange::k2g;   // begin()'s
strider::Mpu6050GyroRange g_gyro = strider::Mpu6050GyroRange::k500Dps;  // begin()'s
char g_command = 0;
Print* g_out = &Serial;  // the port of the command being answered

void event() {
  sensors_event_t a, g, t;
  g_mpu.getEvent(&a, &g, &t);
  const float v[7] = {a.acceleration.x, a.acceleration.y, a.acceleration.z, g.gyro.x, g.gyro.y, g.gyro.z,
                      t.temperature};
  g_out->print("event");
  for (float f : v) {
    g_out->print(' ');
    g_out->print(f, 6);
  }
  g_out->println();
}

float deg(strider::Fixed v) { return v.to_float() * 57.29578f; }

void burst() {
  uint8_t b[strider::kMpu6050BurstBytes];
  const bool ok = read_burst(b);
  g_out->print(ok ? "burst" : "burst failed");
  for (uint8_t x : b) {
    g_out->print(' ');
    g_out->print(x);
  }
  g_out->println();
  const strider::ImuSample<strider::Fixed> s = strider::mpu6050_sample<strider::Fixed>(b, g_accel, g_gyro);
  g_out->print("strider");
  const strider::Fixed v[7] = {s.accel_m_s2.x, s.accel_m_s2.y, s.accel_m_s2.z, s.gyro_rad_s.x,
                               s.gyro_rad_s.y, s.gyro_rad_s.z, s.temp_c};
  for (strider::Fixed f : v) {
    g_out->print(' ');
    g_out->print(f.raw());  // Q16.16: exact
  }
  g_out->println();
}

void filter() {
  strider::AttitudeFilter<float> f;
  strider::AttitudeFilter<strider::Fixed> x;
  uint32_t us_f = 0, us_x = 0;
  const int kUpdates = 100;
  for (int k = 0; k < kUpdates; ++k) {
    sensors_event_t a, g, t;
    g_mpu.getEvent(&a, &g, &t);
    uint8_t b[strider::kMpu6050BurstBytes];
    read_burst(b);
    const strider::ImuSample<strider::Fixed> s = strider::mpu6050_sample<strider::Fixed>(b, g_accel, g_gyro);
    const strider::Vec3<float> acc(a.acceleration.x, a.acceleration.y, a.acceleration.z);
    const strider::Vec3<float> rate(g.gyro.x, g.gyro.y, g.gyro.z);
    uint32_t t0 = micros();
    f.update(acc, rate, 0.02f);
    uint32_t t1 = micros();
    x.update(s, strider::Fixed(0.02));
    uint32_t t2 = micros();
    if (k > 0) {  // the first update only levels
      us_f += t1 - t0;
      us_x += t2 - t1;
    }
    delay(20);
  }
  g_out->print("filter ");
  g_out->print(f.roll_rad() * 57.29578f, 3);
  g_out->print(' ');
  g_out->print(f.pitch_rad() * 57.29578f, 3);
  g_out->print(' ');
  g_out->print(deg(x.roll_rad()), 3);
  g_out->print(' ');
  g_out->print(deg(x.pitch_rad()), 3);
  g_out->print(' ');
  g_out->print(us_f / (kUpdates - 1));
  g_out->print(' ');
  g_out->println(us_x / (kUpdates - 1));
}

void adc() {
  g_out->print("adc");
  const uint8_t pins[8] = {A0, A1, A2, A3, A4, A5, A6, A7};
  for (uint8_t p : pins) {
    g_out->print(' ');
    g_out->print(analogRead(p));
  }
  g_out->println();
}

}  // namespace

void setup() {
  Serial.begin(115200);
  Serial1.begin(9600);
  g_ok = g_mpu.begin();
  Serial.println(g_ok ? "begin ok" : "begin failed");
}

void loop() {
  char c;
  if (Serial.available()) {
    c = char(Serial.read());
    g_out = &Serial;
  } else if (Serial1.available()) {
    c = char(Serial1.read());
    g_out = &Serial1;
  } else {
    return;
  }
  if (g_command == 'a' || g_command == 'g') {
    const uint8_t n = uint8_t((c - '0') & 3);
    if (g_command == 'a') {
      g_mpu.setAccelerometerRange(mpu6050_accel_range_t(n));
      g_accel = strider::Mpu6050AccelRange(n);
    } else {
      g_mpu.setGyroRange(mpu6050_gyro_range_t(n));
      g_gyro = strider::Mpu6050GyroRange(n);
    }
    g_out->print(g_command == 'a' ? "ok accel " : "ok gyro ");
    g_out->println(n);
    g_command = 0;
    return;
  }
  switch (c) {
    case 'r': event(); break;
    case 'b': burst(); break;
    case 'f': filter(); break;
    case 'v': adc(); break;
    case 'a':
    case 'g': g_command = c; break;
    default: break;
  }
}
