//! CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final
//! xor), bitwise: the settings record and checked lines.
#ifndef STRIDER_CONTROL_CRC_H
#define STRIDER_CONTROL_CRC_H

#include <stddef.h>
#include <stdint.h>

namespace strider {

constexpr uint16_t kCrc16Init = 0xFFFFu;  //!< start value of CRC-16/CCITT-FALSE

//! One byte into a running CRC-16/CCITT-FALSE.
inline uint16_t crc16_ccitt_update(uint16_t crc, uint8_t byte) {
  crc = uint16_t(crc ^ uint16_t(uint16_t(byte) << 8));
  for (uint8_t bit = 0; bit < 8; ++bit) {
    crc = (crc & 0x8000u) ? uint16_t(uint16_t(crc << 1) ^ 0x1021u) : uint16_t(crc << 1);
  }
  return crc;
}

//! CRC-16/CCITT-FALSE of a buffer ("123456789" -> 0x29B1).
inline uint16_t crc16_ccitt(const uint8_t* data, size_t size, uint16_t crc = kCrc16Init) {
  for (size_t i = 0; i < size; ++i) crc = crc16_ccitt_update(crc, data[i]);
  return crc;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_CRC_H
