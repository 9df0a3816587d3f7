// DelayBuffer semantics (docs/delay-and-study.md, "Delayed feedback").
#include <gtest/gtest.h>

#include "aurora_control/loop/delay_buffer.h"

using aurora_control::DelayBuffer;
using aurora_control::delayedHistoryIndex;

TEST(DelayBuffer, FollowsTheSpecRule) {
  // H(k) = k here; at iteration k the controller receives H(k - d) if k > d,
  // else H(k).
  for (long d = 0; d < 8; ++d) {
    DelayBuffer<long, 8> buffer;
    for (long k = 1; k <= 30; ++k) {
      buffer.push(k);
      const long expected = k > d ? k - d : k;
      EXPECT_EQ(buffer.delayed(d), expected) << "k=" << k << " d=" << d;
      EXPECT_EQ(delayedHistoryIndex(k, d), expected);
      EXPECT_EQ(delayedHistoryIndex(int(k), int(d)), int(expected));
      EXPECT_EQ(buffer.delayInForce(d), k > d ? d : 0);
    }
  }
}

TEST(DelayBuffer, ZeroDelayIsNewest) {
  DelayBuffer<int, 4> buffer;
  buffer.push(7);
  buffer.push(9);
  EXPECT_EQ(buffer.delayed(0), 9);
}

TEST(DelayBuffer, WrapsAroundAtCapacity) {
  DelayBuffer<long, 4> buffer;  // holds delays 0..3
  for (long k = 1; k <= 11; ++k) buffer.push(k);
  EXPECT_EQ(buffer.delayed(3), 8);
  EXPECT_EQ(buffer.delayed(1), 10);
  using Buffer4 = DelayBuffer<long, 4>;
  EXPECT_TRUE(Buffer4::supportsDelay(3));
  EXPECT_FALSE(Buffer4::supportsDelay(4));
  EXPECT_FALSE(Buffer4::supportsDelay(-1));
}

TEST(DelayBuffer, ClearRestartsHistory) {
  DelayBuffer<long, 4> buffer;
  for (long k = 1; k <= 5; ++k) buffer.push(k);
  buffer.clear();
  EXPECT_EQ(buffer.size(), 0);
  buffer.push(42);
  EXPECT_EQ(buffer.delayed(3), 42);  // fewer samples than the delay: current state
}

TEST(DelayBuffer, PendingCountsTheStatesUntilTheDelayIsInForce) {
  // A delay raised live beyond the history kept is not in force (0) until
  // d + 1 samples exist: the pending count says how many more are needed.
  DelayBuffer<long, 64> buffer;
  for (long k = 1; k <= 10; ++k) buffer.push(k);
  EXPECT_EQ(buffer.pendingUntilInForce(5), 0);
  EXPECT_EQ(buffer.delayInForce(5), 5);
  EXPECT_EQ(buffer.pendingUntilInForce(40), 31);  // raised to 40 with 10 kept
  EXPECT_EQ(buffer.delayInForce(40), 0);
  for (long k = 11; k <= 40; ++k) buffer.push(k);
  EXPECT_EQ(buffer.pendingUntilInForce(40), 1);
  buffer.push(41);
  EXPECT_EQ(buffer.pendingUntilInForce(40), 0);
  EXPECT_EQ(buffer.delayInForce(40), 40);
}
