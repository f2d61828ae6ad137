//! The named gaits: quadrupeds walk, trot, pace, crawl; hexapods tripod,
//! ripple, wave; and which gaits a model supports. Their sources and
//! footfall diagrams: docs/gaits.md, "Gait tables".
#ifndef STRIDER_GAIT_GAIT_LIBRARY_H
#define STRIDER_GAIT_GAIT_LIBRARY_H

#include <string.h>

#include "../math/flash_table.h"
#include "gait_table.h"

//! The gait tables and their lists are in flash on the AVR (no RAM for seven tables).
#define STRIDER_GAIT_STORAGE STRIDER_PROGMEM

namespace strider {

//! 4-beat walk, seed 003 fig. 7b: four-foot windows of 0.10 between the
//! swings let the body carry its CoM into the next support triangle.
constexpr GaitTable kGaitWalk STRIDER_GAIT_STORAGE = {"walk", 4, 0.85f, {0.25f, 0.75f, 0.0f, 0.5f, 0.0f, 0.0f}, true, true};

//! Trot, seed 003 section 4 C: diagonal pairs (LF + RH, LH + RF) alternate.
constexpr GaitTable kGaitTrot STRIDER_GAIT_STORAGE = {"trot", 4, 0.5f, {0.0f, 0.5f, 0.0f, 0.5f, 0.0f, 0.0f}, false, false};

//! Pace, seed 003 section 4 B: lateral pairs (LF + LH, RH + RF) alternate.
constexpr GaitTable kGaitPace STRIDER_GAIT_STORAGE = {"pace", 4, 0.5f, {0.0f, 0.0f, 0.5f, 0.5f, 0.0f, 0.0f}, false, false};

//! Seed 000 section 3.3's six-step crawl: the diagonal pairs alternate, with
//! four-foot windows of 1/6 between them (docs/gaits.md).
constexpr GaitTable kGaitCrawl STRIDER_GAIT_STORAGE = {"crawl", 4, 2.0f / 3.0f, {0.0f, 0.5f, 0.0f, 0.5f, 0.0f, 0.0f}, true, true};

//! Tripod: alternating tripods {0, 2, 4} and {1, 3, 5}.
constexpr GaitTable kGaitTripod STRIDER_GAIT_STORAGE = {"tripod", 6, 0.5f, {0.0f, 0.5f, 0.0f, 0.5f, 0.0f, 0.5f}, false, false};

//! Ripple: a back-to-front wave on each side, the sides half a cycle apart.
constexpr GaitTable kGaitRipple STRIDER_GAIT_STORAGE = {
    "ripple", 6, 2.0f / 3.0f, {2.0f / 3.0f, 1.0f / 3.0f, 0.0f, 0.5f, 5.0f / 6.0f, 1.0f / 6.0f}, false, false};

//! Wave: one leg at a time, rear to front on the left, then on the right.
constexpr GaitTable kGaitWave STRIDER_GAIT_STORAGE = {
    "wave", 6, 5.0f / 6.0f, {2.0f / 6.0f, 1.0f / 6.0f, 0.0f, 3.0f / 6.0f, 4.0f / 6.0f, 5.0f / 6.0f}, false, false};

static_assert(gait_table::valid(kGaitWalk) && gait_table::valid(kGaitTrot) && gait_table::valid(kGaitPace) &&
                  gait_table::valid(kGaitCrawl) && gait_table::valid(kGaitTripod) &&
                  gait_table::valid(kGaitRipple) && gait_table::valid(kGaitWave),
              "gait tables: offsets in [0, 1), duty in (0, 1)");
static_assert(gait_table::keeps_support(kGaitWalk, 3) && gait_table::keeps_support(kGaitCrawl, 2) &&
                  gait_table::keeps_support(kGaitTrot, 2) && gait_table::keeps_support(kGaitPace, 2),
              "quadruped gaits keep enough feet down");
static_assert(gait_table::keeps_support(kGaitTripod, 3) && gait_table::keeps_support(kGaitRipple, 4) &&
                  gait_table::keeps_support(kGaitWave, 5),
              "hexapod gaits keep enough feet down");
static_assert(gait_table::swings_separated(kGaitWalk) && gait_table::swings_separated(kGaitCrawl),
              "body-shifting gaits need separated swings");

//! The gaits of one leg count.
struct GaitList {
  const GaitTable* const* items;
  uint8_t count;
};

namespace gait_library_detail {
constexpr const GaitTable* kQuadruped[] STRIDER_GAIT_STORAGE = {&kGaitWalk, &kGaitTrot, &kGaitPace, &kGaitCrawl};
constexpr const GaitTable* kHexapod[] STRIDER_GAIT_STORAGE = {&kGaitTripod, &kGaitRipple, &kGaitWave};
//! The list (in flash on the AVR) and its length for a leg count.
constexpr const GaitTable* const* list_items(uint8_t leg_count) {
  return leg_count == 4 ? kQuadruped : leg_count == 6 ? kHexapod : nullptr;
}
constexpr uint8_t list_count(uint8_t leg_count) { return leg_count == 4 ? 4 : leg_count == 6 ? 3 : 0; }
//! Entry i of a list: on the AVR its address is read from flash.
inline const GaitTable* list_entry(const GaitTable* const* items, uint8_t i) {
#if defined(__AVR__)
  static_assert(sizeof(const GaitTable*) == 2, "AVR data pointers are 16-bit");
  return reinterpret_cast<const GaitTable*>(flash_u16(reinterpret_cast<const uint16_t*>(items), i));
#else
  return items[i];
#endif
}
//! A name in RAM equal to one in flash (strcmp_P, without avr/pgmspace.h).
inline bool same_as_flash(const char* name, const char* flash_name) {
  for (uint8_t i = 0;; ++i) {
    const char c = char(flash_u8(flash_name + i));
    if (c != name[i]) return false;
    if (c == 0) return true;
  }
}
}  // namespace gait_library_detail

//! The names of the gaits of a leg count, space-separated in list order, as
//! replies name them (`help`, `err 23`): always in flash on the AVR, read
//! through flash_u8(); "" for a leg count without gaits.
constexpr char kQuadrupedGaitNames[] STRIDER_PROGMEM = "walk trot pace crawl";
constexpr char kHexapodGaitNames[] STRIDER_PROGMEM = "tripod ripple wave";
constexpr char kNoGaitNames[] STRIDER_PROGMEM = "";
constexpr const char* gait_names(uint8_t leg_count) {
  return leg_count == 4 ? kQuadrupedGaitNames : leg_count == 6 ? kHexapodGaitNames : kNoGaitNames;
}

//! Where gait `name` is in the list of a robot with leg_count legs (the
//! order of gait_names()); kNoGaitIndex: not there.
constexpr uint8_t kNoGaitIndex = 0xFF;
inline uint8_t gait_index(uint8_t leg_count, const char* name) {
  if (name == nullptr) return kNoGaitIndex;
  const GaitTable* const* items = gait_library_detail::list_items(leg_count);
  for (uint8_t i = 0; i < gait_library_detail::list_count(leg_count); ++i)
    if (gait_library_detail::same_as_flash(name, gait_library_detail::list_entry(items, i)->name)) return i;
  return kNoGaitIndex;
}

//! The gait called `name` with `leg_count` legs into *out (copied out of
//! flash on the AVR); false (out untouched) when there is none.
inline bool load_gait(uint8_t leg_count, const char* name, GaitTable* out) {
  const uint8_t i = gait_index(leg_count, name);
  if (i == kNoGaitIndex) return false;
  flash_copy(out, gait_library_detail::list_entry(gait_library_detail::list_items(leg_count), i), sizeof *out);
  return true;
}
inline bool load_gait(const RobotModel& model, const char* name, GaitTable* out) {
  return load_gait(model.leg_count, name, out);
}

#if !defined(__AVR__)
//! The gaits a model supports: every gait of its leg count.
constexpr GaitList gaits_for(const RobotModel& model) {
  return GaitList{gait_library_detail::list_items(model.leg_count), gait_library_detail::list_count(model.leg_count)};
}

//! The gait called `name` that `model` supports, or nullptr.
inline const GaitTable* find_gait(const RobotModel& model, const char* name) {
  const uint8_t i = gait_index(model.leg_count, name);
  return i == kNoGaitIndex ? nullptr : gaits_for(model).items[i];
}
#endif

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_LIBRARY_H
