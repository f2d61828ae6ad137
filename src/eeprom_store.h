// The Mega's 4 KB EEPROM as a strider ByteStore (hal_interfaces.h). Writes
// skip unchanged bytes (eeprom_update_byte: the cells last ~100,000 writes)
// and are read back, so a worn cell is reported instead of trusted.
#ifndef STRIDER_EEPROM_STORE_H
#define STRIDER_EEPROM_STORE_H

#include <avr/eeprom.h>
#include <stdint.h>

struct EepromStore {
  uint16_t size() const { return uint16_t(E2END) + 1u; }
  uint8_t read(uint16_t addr) const { return eeprom_read_byte(reinterpret_cast<const uint8_t*>(addr)); }
  bool write(uint16_t addr, uint8_t v) {
    eeprom_update_byte(reinterpret_cast<uint8_t*>(addr), v);
    return read(addr) == v;
  }
};

#endif
