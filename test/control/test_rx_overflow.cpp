// RxOverflowWatch against a simulated receive ring that drops bytes while it
// is full (as HardwareSerial does): every real gap is reported before the
// first byte after it, and nothing is reported while the ring never fills.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>

#include "control/rx_overflow.h"

namespace {

struct Result {
  int gaps = 0;       // real gaps (a byte read that does not follow the previous one)
  int missed = 0;     // real gaps not reported
  int reported = 0;   // reports
  int reads = 0;
};

// A sender writes numbered bytes, a reader reads them at random moments from
// a ring of `capacity`; p_write is the chance per step that a byte arrives.
Result simulate(uint32_t seed, uint16_t capacity, double p_write, double p_read, int steps) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::deque<uint32_t> ring;
  strider::RxOverflowWatch watch;
  uint32_t sent = 0;
  int64_t last = -1;
  Result r;
  for (int i = 0; i < steps; ++i) {
    if (u(rng) < p_write) {
      if (ring.size() < capacity) ring.push_back(sent);  // else dropped, silently
      ++sent;
    }
    if (!ring.empty() && u(rng) < p_read) {
      const bool reported = watch.gap_before_next(uint16_t(ring.size()), capacity);
      const uint32_t b = ring.front();
      ring.pop_front();
      const bool gap = int64_t(b) != last + 1;
      last = b;
      ++r.reads;
      r.gaps += gap;
      r.reported += reported;
      r.missed += gap && !reported;
    }
  }
  return r;
}

TEST(RxOverflowWatch, ReportsEveryGap) {
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    // A reader slower than the sender, in bursts: the ring overflows often.
    const Result r = simulate(seed, uint16_t(4 + seed % 13), 0.5, 0.2 + 0.005 * seed, 20000);
    EXPECT_GT(r.gaps, 0) << seed;
    EXPECT_EQ(r.missed, 0) << "seed " << seed << ": " << r.gaps << " gaps";
    EXPECT_GE(r.reported, r.gaps);
  }
}

TEST(RxOverflowWatch, QuietWhileTheRingNeverFills) {
  for (uint32_t seed = 1; seed <= 20; ++seed) {
    const Result r = simulate(seed, 255, 0.3, 0.9, 20000);
    EXPECT_EQ(r.gaps, 0);
    EXPECT_EQ(r.reported, 0) << seed;
  }
}

TEST(RxOverflowWatch, ReportsTheByteAfterTheRingsContents) {
  strider::RxOverflowWatch w;
  // The ring holds 3 of at most 3: whatever was dropped comes after them.
  EXPECT_FALSE(w.gap_before_next(3, 3));  // byte 0
  EXPECT_FALSE(w.gap_before_next(2, 3));  // byte 1
  EXPECT_FALSE(w.gap_before_next(1, 3));  // byte 2
  EXPECT_TRUE(w.gap_before_next(1, 3));   // byte 3: the first after the gap
  EXPECT_FALSE(w.gap_before_next(1, 3));
  // Full at two reads in a row: a gap may follow either's last byte.
  EXPECT_FALSE(w.gap_before_next(3, 3));  // byte 5, gap before 8
  EXPECT_FALSE(w.gap_before_next(3, 3));  // byte 6, gap before 9
  EXPECT_FALSE(w.gap_before_next(2, 3));  // byte 7
  EXPECT_TRUE(w.gap_before_next(2, 3));   // byte 8
  EXPECT_TRUE(w.gap_before_next(1, 3));   // byte 9
  EXPECT_FALSE(w.gap_before_next(1, 3));  // byte 10
}

}  // namespace
