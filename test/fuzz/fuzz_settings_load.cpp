// libFuzzer target: arbitrary store contents through the settings loader.
// Whatever the bytes, the loader must return settings that pass
// settings_valid(), and only kOk may return anything but the defaults.
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "control/hal_interfaces.h"
#include "control/settings_store.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  strider::ArrayByteStore<128> store;
  store.erase();
  // Half the inputs start from a valid record, so mutations explore near it.
  if (size > 0 && (data[0] & 1u)) {
    strider::save_settings(store, strider::default_settings());
    ++data;
    --size;
  }
  const size_t n = size < sizeof store.bytes ? size : sizeof store.bytes;
  for (size_t i = 0; i < n; ++i) store.bytes[i] ^= data[i];
  strider::Settings s;
  const strider::SettingsStatus st = strider::load_settings(store, &s);
  if (!strider::settings_valid(s)) abort();
  if (st != strider::SettingsStatus::kOk) {
    const strider::Settings d = strider::default_settings();
    uint8_t a[strider::kSettingsPayloadBytes], b[strider::kSettingsPayloadBytes];
    strider::encode_settings(s, a);
    strider::encode_settings(d, b);
    if (memcmp(a, b, sizeof a) != 0) abort();
  } else {
    // A record that loads must save and load back identically.
    strider::ArrayByteStore<128> copy;
    copy.erase();
    if (strider::save_settings(copy, s) != strider::SettingsStatus::kOk) abort();
    strider::Settings back;
    if (strider::load_settings(copy, &back) != strider::SettingsStatus::kOk) abort();
  }
  return 0;
}
