// The turn every lane engine gives its lanes (LaneSlots, lane_work.h): a
// lane whose run ended records its result once and takes the next
// combination; with none left, a spare run whose result is dropped, which
// an early stop does not restart.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "../src/lanes/lane_work.h"

namespace {

using namespace aurora_sweep;

constexpr int kLanes = 4;

struct Slots {
  GridView grid{};
  std::vector<SimResult> out;
  std::atomic<long> next{0};
  Progress progress{0};
  LaneWork work;
  LaneSlots<kLanes> slots{work};
  long started[kLanes];  // each lane's last start: its combination, or -1 - it for a spare
  explicit Slots(long combinations)
      : out(static_cast<size_t>(combinations)), work(view(combinations), 0, combinations, out, next, progress) {}

  static GridView view(long combinations) {
    GridView g{};
    g.repeats = combinations;  // no axis: each repeat is a combination
    return g;
  }
  void refill() {
    for (long& s : started) s = -100;
    slots.refill([&](long& index) { return work.take(index); }, work.first(),
                 [&](int l, long index, bool counts) { started[l] = counts ? index : -1 - index; });
  }
  // Lane l's run ends (stopped early, or at its last step).
  void end(int l, bool stopped, bool last) {
    bool s[kLanes] = {}, e[kLanes] = {};
    s[l] = stopped, e[l] = last;
    slots.end(s, e, [&](int lane) {
      SimResult r{};
      r.steps = 100 + lane;
      return r;
    });
  }
};

TEST(LaneSlots, AnEndedLaneRecordsItsResultOnceAndTakesTheNext) {
  Slots s(6);
  s.refill();
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(s.started[l], l);  // every lane free at first
  EXPECT_TRUE(s.slots.anyCounts());

  s.end(2, true, false);  // an early stop
  EXPECT_EQ(s.progress.load(), 1);
  EXPECT_EQ(s.out[2].steps, 102);
  s.end(2, true, true);  // already free: nothing recorded twice
  EXPECT_EQ(s.progress.load(), 1);
  s.refill();
  EXPECT_EQ(s.started[2], 4);
  for (int l : {0, 1, 3}) EXPECT_EQ(s.started[l], -100) << "lane " << l << " is still running";

  s.end(0, false, true);  // its last step
  s.refill();
  EXPECT_EQ(s.started[0], 5);
  EXPECT_EQ(s.out[0].steps, 100);
}

TEST(LaneSlots, WithoutWorkALaneRunsASpareThatOnlyItsLastStepEnds) {
  Slots s(2);
  s.refill();
  EXPECT_EQ(s.started[0], 0);
  EXPECT_EQ(s.started[1], 1);
  EXPECT_EQ(s.started[2], -1);  // the range's first, not counted
  EXPECT_EQ(s.started[3], -1);

  s.end(2, true, false);  // a spare's early stop does not restart it
  s.refill();
  EXPECT_EQ(s.started[2], -100);
  EXPECT_EQ(s.progress.load(), 0);

  s.end(2, false, true);  // past its last step it runs the spare again, still not counted
  s.refill();
  EXPECT_EQ(s.started[2], -1);
  EXPECT_EQ(s.progress.load(), 0);

  s.end(0, true, false);
  s.end(1, false, true);
  EXPECT_EQ(s.progress.load(), 2);
  EXPECT_FALSE(s.slots.anyCounts());  // every result is in: the batch is done
  s.slots.clear();
  s.refill();
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(s.started[l], -1);
}

}  // namespace
