//! All built-in robot models, in the order of docs/robots.md, and lookup by name.
#ifndef STRIDER_ROBOTS_ALL_ROBOTS_H
#define STRIDER_ROBOTS_ALL_ROBOTS_H

#include <string.h>

#include "dog12.h"
#include "hexapod18.h"
#include "mammal8.h"
#include "spider12.h"
#include "sprawl8.h"

namespace strider {

constexpr uint8_t kRobotCount = 5;

constexpr const RobotModel* kAllRobots[kRobotCount] = {&kSprawl8, &kMammal8, &kDog12, &kHexapod18, &kSpider12};

//! The model called `name`, or nullptr.
inline const RobotModel* find_robot(const char* name) {
  if (name == nullptr) return nullptr;
  for (uint8_t i = 0; i < kRobotCount; ++i)
    if (strcmp(kAllRobots[i]->name, name) == 0) return kAllRobots[i];
  return nullptr;
}

namespace model_checks {
//! Names are unique (the CLI looks models up by name).
constexpr bool names_unique() {
  for (uint8_t i = 0; i < kRobotCount; ++i)
    for (uint8_t k = 0; k < i; ++k)
      if (same_name(kAllRobots[i]->name, kAllRobots[k]->name)) return false;
  return true;
}
}  // namespace model_checks

static_assert(model_checks::names_unique(), "robot names must be unique");

}  // namespace strider

#endif  // STRIDER_ROBOTS_ALL_ROBOTS_H
