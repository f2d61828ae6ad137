//! How the benchmark firmware talks to the simulator host: three general
//! purpose I/O registers of the ATmega2560 that nothing else uses.
//!
//! - GPIOR0 <- entry id: start of one timed call (the host records the cycle).
//! - GPIOR1 <- entry id: end of that call.
//! - GPIOR2 <- one character of a text stream, lines of:
//!     "N name"       a benchmark entry begins; its start/end pairs follow
//!     "S name"       a section of bit-exact results begins
//!     "R h h h ..."  one record of raw int32 results, 8 hex digits each
//!     "I key value"  information (e.g. "I stride 4")
//!     "E"            the run is complete
//!   Before the run the host preloads GPIOR2 with a mode byte (kMode* bits);
//!   the firmware reads it once at reset (crt0 does not touch GPIOR2).
//! The firmware ends with cli(); sleep, which stops simavr.
#ifndef STRIDER_TOOLS_BENCH_PROTOCOL_H
#define STRIDER_TOOLS_BENCH_PROTOCOL_H

// Data-space addresses (I/O address + 0x20) for simavr's register hooks.
#define STRIDER_BENCH_ADDR_START 0x3E  // GPIOR0, I/O 0x1E
#define STRIDER_BENCH_ADDR_END 0x4A    // GPIOR1, I/O 0x2A
#define STRIDER_BENCH_ADDR_TEXT 0x4B   // GPIOR2, I/O 0x2B

// Mode bits preloaded into GPIOR2.
#define STRIDER_BENCH_MODE_QUICK 0x01     // every 8th input only (ctest)
#define STRIDER_BENCH_MODE_NO_BENCH 0x02  // skip the timed entries
#define STRIDER_BENCH_MODE_NO_EXACT 0x04  // skip the bit-exact sections

#endif  // STRIDER_TOOLS_BENCH_PROTOCOL_H
