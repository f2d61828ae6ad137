// An Arduino IDE sketch as the IDE compiles it: Arduino.h first (with its
// min, max, abs, round, constrain, sq, radians and degrees macros), then the
// umbrella header. Compiled by ctest against Debian's Arduino core.
#include <Arduino.h>
#include <strider.h>

strider::Fixed g_scale(3);

void setup() {
  Serial.begin(9600);
  Serial.println(max(1, 2));             // the Arduino macro still works after strider.h
  Serial.println(constrain(5, 0, 3));
  Serial.println(strider::max_of(g_scale, strider::Fixed(2)).to_float());
}

void loop() {}
