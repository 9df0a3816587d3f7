// Rejected-input logging: one warning per burst, a periodic summary, an end
// line only after a quiet period.
#include <gtest/gtest.h>

#include <vector>

#include "aurora_sim/rejection_burst.h"

using aurora_sim::BurstReport;
using aurora_sim::RejectionBurst;

namespace {
// A 30 Hz publisher of NaN interleaved with a 30 Hz publisher of valid
// commands (the controller) for `seconds`; returns the report kinds.
std::vector<BurstReport> interleaved(RejectionBurst& burst, double t0, double seconds) {
  std::vector<BurstReport> lines;
  for (double t = t0; t < t0 + seconds; t += 1.0 / 30.0) {
    BurstReport r = burst.poll(t);
    if (r.kind != BurstReport::kNone) lines.push_back(r);
    r = burst.rejected(t);
    if (r.kind != BurstReport::kNone) lines.push_back(r);
    r = burst.poll(t + 0.01);
    if (r.kind != BurstReport::kNone) lines.push_back(r);
    burst.accepted();
  }
  return lines;
}
}  // namespace

TEST(RejectionBurst, InterleavedValidInputDoesNotEndTheBurst) {
  RejectionBurst burst(1.0, 5.0);
  const std::vector<BurstReport> lines = interleaved(burst, 0.0, 3.4);
  ASSERT_EQ(lines.size(), 1u);  // the old rule gave ~100 warnings and ~100 info lines here
  EXPECT_EQ(lines[0].kind, BurstReport::kStarted);
  EXPECT_TRUE(burst.active());
}

TEST(RejectionBurst, SummaryEveryPeriodAndEndAfterQuiet) {
  RejectionBurst burst(1.0, 5.0);
  const std::vector<BurstReport> lines = interleaved(burst, 0.0, 12.0);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1].kind, BurstReport::kSummary);
  EXPECT_NEAR(double(lines[1].rejected), 150.0, 2.0);  // 5 s at 30 Hz
  EXPECT_NEAR(double(lines[1].accepted), 150.0, 2.0);
  EXPECT_NEAR(lines[1].span, 5.0, 0.05);
  EXPECT_EQ(lines[2].kind, BurstReport::kSummary);
  EXPECT_EQ(burst.poll(12.5).kind, BurstReport::kNone);  // 0.5 s quiet: not ended yet
  const BurstReport end = burst.poll(13.1);
  EXPECT_EQ(end.kind, BurstReport::kEnded);
  EXPECT_NEAR(double(end.rejected), 360.0, 2.0);
  EXPECT_FALSE(burst.active());
  EXPECT_EQ(burst.poll(20.0).kind, BurstReport::kNone);
}

TEST(RejectionBurst, ANewBurstAfterTheQuietPeriodWarnsAgain) {
  RejectionBurst burst(1.0, 5.0);
  EXPECT_EQ(burst.rejected(0.0).kind, BurstReport::kStarted);
  EXPECT_EQ(burst.poll(0.9).kind, BurstReport::kNone);
  EXPECT_EQ(burst.rejected(0.9).kind, BurstReport::kNone);  // same burst
  EXPECT_EQ(burst.poll(2.0).kind, BurstReport::kEnded);
  EXPECT_EQ(burst.rejected(2.1).kind, BurstReport::kStarted);
}
