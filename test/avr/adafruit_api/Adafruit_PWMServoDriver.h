// DECLARATIONS ONLY, for a compile check: the part of the Adafruit PWM Servo
// Driver Library's public API (version 3.x, Adafruit_PWMServoDriver.h) that
// src/pca9685_bus_adafruit.cpp calls, with the library's signatures. The
// library itself is not installable in the offline build; this lets ctest
// compile the PlatformIO backend against its API. Nothing links with it.
#ifndef STRIDER_TEST_ADAFRUIT_PWMSERVODRIVER_API_H
#define STRIDER_TEST_ADAFRUIT_PWMSERVODRIVER_API_H

#include <Arduino.h>
#include <Wire.h>

class Adafruit_PWMServoDriver {
 public:
  Adafruit_PWMServoDriver();
  Adafruit_PWMServoDriver(const uint8_t addr);
  Adafruit_PWMServoDriver(const uint8_t addr, TwoWire &i2c);
  bool begin(uint8_t prescale = 0);
  void reset();
  void sleep();
  void wakeup();
  void setExtClk(uint8_t prescale);
  void setPWMFreq(float freq);
  void setOutputMode(bool totempole);
  uint16_t getPWM(uint8_t num, bool off = false);
  uint8_t setPWM(uint8_t num, uint16_t on, uint16_t off);
  void setPin(uint8_t num, uint16_t val, bool invert = false);
  uint8_t readPrescale(void);
  void writeMicroseconds(uint8_t num, uint16_t Microseconds);
  void setOscillatorFrequency(uint32_t freq);
  uint32_t getOscillatorFrequency(void);
};

#endif
