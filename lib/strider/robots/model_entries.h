//! ModelEntries: the entries of a table listed per model (each entry names
//! its model in `robot`) that a build keeps, picked at compile time: every
//! entry on the host (kEveryModel), only its own model's in a firmware
//! (FirmwareProfile::kModelIndex), so the other models' entries take no
//! flash there.
#ifndef STRIDER_ROBOTS_MODEL_ENTRIES_H
#define STRIDER_ROBOTS_MODEL_ENTRIES_H

#include <stddef.h>
#include <stdint.h>

#include "../math/flash_table.h"
#include "all_robots.h"
#include "build_profile.h"
#include "model_checks.h"

namespace strider {

//! Whether an entry for the model called `robot` belongs to the build of
//! model index `model` (kEveryModel: all of them).
constexpr bool entry_for_model(const char* robot, uint8_t model) {
  return model == kEveryModel || (model < kRobotCount && model_checks::same_name(robot, kAllRobots[model]->name));
}

//! How many entries of `all` the build of model index `model` keeps.
template <typename T, size_t N>
constexpr uint8_t model_entry_count(const T (&all)[N], uint8_t model) {
  uint8_t n = 0;
  for (size_t i = 0; i < N; ++i)
    if (entry_for_model(all[i].robot, model)) ++n;
  return n;
}

//! kCount entries, in the table's order (one unused slot when there are none).
template <typename T, uint8_t kCount>
struct ModelEntries {
  T at[kCount > 0 ? kCount : 1];
};

//! The entries of `all` for the build of model index `model`.
template <typename T, uint8_t kCount, size_t N>
constexpr ModelEntries<T, kCount> model_entries(const T (&all)[N], uint8_t model) {
  ModelEntries<T, kCount> e{};
  uint8_t n = 0;
  for (size_t i = 0; i < N; ++i)
    if (entry_for_model(all[i].robot, model)) e.at[n++] = all[i];
  return e;
}

//! The entries of a per-model table that the build of model index kModel
//! keeps, in flash: kCount of them, in kTable.at. Table names the whole
//! table: `using Entry = T;` and `static constexpr const T (&all())[N]`
//! (a function: avr-gcc 5 takes no internal-linkage array as a template
//! argument).
template <typename Table, uint8_t kModel>
struct ModelTable {
  using Entry = typename Table::Entry;
  static constexpr uint8_t kCount = model_entry_count(Table::all(), kModel);
  static constexpr ModelEntries<Entry, kCount> kTable STRIDER_PROGMEM =
      model_entries<Entry, kCount>(Table::all(), kModel);
};
template <typename Table, uint8_t kModel>
constexpr uint8_t ModelTable<Table, kModel>::kCount;
template <typename Table, uint8_t kModel>
constexpr ModelEntries<typename Table::Entry, ModelTable<Table, kModel>::kCount> ModelTable<Table, kModel>::kTable;

}  // namespace strider

#endif  // STRIDER_ROBOTS_MODEL_ENTRIES_H
