// real.launch link:=wifi_congested against the driver-compatible fake
// (docs/links.md): the model's link sits between the real drone's states and
// the law, and between the law and the driver, while the safety layer and
// its watchdogs keep seeing the real, undelayed states. The mission
// completes; the link loses states and commands, delays them, makes the
// drone hover on a stale command; and outages of the model's uplink longer
// than the watchdog's hover_after do not trigger the stale-state hover.
#include <aurora_msgs/Control.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

// Longest run of consecutive flying cycles in which no new state reached the law.
long longestUplinkOutage(const std::vector<aurora_msgs::Control>& fly) {
  long run = 0, longest = 0;
  for (const auto& c : fly) {
    run = c.state_arrived ? 0 : run + 1;
    longest = std::max(longest, run);
  }
  return longest;
}

bool watchdogHovers(const aurora_msgs::Control& c) { return c.mode.find("no fresh state") != std::string::npos; }

// The model's uplink outages longer than `cycles` during the task (from the
// first "fly" to the landing), and in how many of them a watchdog hovered.
struct Outages {
  long longer = 0, hovered = 0;
};
Outages outagesLongerThan(const std::vector<aurora_msgs::Control>& all, long cycles) {
  Outages o;
  long run = 0;
  bool hovered = false, flying = false;
  auto close = [&] {
    if (run > cycles) {
      ++o.longer;
      o.hovered += hovered;
    }
    run = 0;
    hovered = false;
  };
  for (const auto& c : all) {
    flying = (flying || c.mode == "fly") && c.mode.rfind("land", 0) != 0;
    if (!flying || c.state_arrived) {
      close();
      continue;
    }
    ++run;
    hovered = hovered || watchdogHovers(c);
  }
  close();
  return o;
}

}  // namespace

TEST(RealLink, TheModelsLinkSitsBetweenTheRealDroneAndTheLawNotTheWatchdogs) {
  ros::NodeHandle nh, pnh("~");
  std::vector<aurora_msgs::Control> all, fly;
  bool done = false;
  ros::Subscriber sub = nh.subscribe<aurora_msgs::Control>("control", 5000, [&](const aurora_msgs::Control::ConstPtr& m) {
    all.push_back(*m);
    if (m->mode == "fly") fly.push_back(*m);
    if (m->mode == "landed") done = true;
  });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(pnh.param("timeout", 110.0));
  while (ros::ok() && !done && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_TRUE(done) << "the flight did not end with 'landed' in time (last mode '"
                    << (all.empty() ? std::string("none") : all.back().mode) << "')";
  bool complete = false;
  long watchdog_hovers = 0;
  for (const auto& c : all) {
    complete |= c.mode == "land (task complete)";
    watchdog_hovers += watchdogHovers(c);
  }
  EXPECT_TRUE(complete) << "the mission did not end by completing its task";
  ASSERT_GT(fly.size(), 1700u);

  // The link at work: losses on both directions, states kept, the base delay
  // and the jitter in the state's age, commands of age >= the downlink's
  // delay, the drone hovering on a stale command.
  const auto& last = fly.back();
  long kept = 0, hovers = 0, min_age_arrived = 1 << 30, max_age = 0, min_command_age = 1 << 30;
  for (const auto& c : fly) {
    kept += !c.state_arrived;
    hovers += c.drone_hovers;
    if (c.state_arrived && c.step > 100) min_age_arrived = std::min<long>(min_age_arrived, c.delay_in_force);
    max_age = std::max<long>(max_age, c.delay_in_force);
    if (c.command_age >= 0) min_command_age = std::min<long>(min_command_age, c.command_age);
    if (c.drone_hovers) {
      for (double u : c.command) EXPECT_EQ(u, 0.0) << "a hovering drone applies no command";
    }
  }
  const long outage = longestUplinkOutage(fly);
  std::printf("real.launch over wifi_congested: %zu flying cycles, losses up %u down %u, states kept %ld, "
              "longest uplink outage %ld cycles, state age %ld..%ld, command age >= %ld, drone hovers %ld cycles\n",
              fly.size(), last.uplink_losses, last.downlink_losses, kept, outage, min_age_arrived, max_age,
              min_command_age, hovers);
  EXPECT_GT(last.uplink_losses, 0u);
  EXPECT_GT(last.downlink_losses, 0u);
  EXPECT_GT(kept, 0);
  EXPECT_EQ(min_age_arrived, 2) << "the uplink's base delay (links/wifi_congested.yaml: 2)";
  EXPECT_GT(max_age, 2) << "jitter and losses age the state";
  EXPECT_EQ(min_command_age, 2) << "the downlink's base delay (2)";
  EXPECT_GT(hovers, 0);
  // The watchdog hovers after 0.2 s (6 cycles) without a fresh state. Had it
  // watched the model's link, it would have hovered in each of the model's
  // uplink outages longer than that. A real stall of the states (the fake
  // driver held up on a loaded machine) does make it hover, rightly, and may
  // fall in one: most outages must pass without a hover.
  EXPECT_GT(outage, 6);
  const Outages o = outagesLongerThan(all, 6);
  std::printf("%ld of the model's uplink outages were longer than 6 cycles; a watchdog hovered in %ld of them "
              "(%ld watchdog hover cycles in all)\n", o.longer, o.hovered, watchdog_hovers);
  EXPECT_GE(o.longer, 2) << "too few long outages of the model's uplink to tell what the watchdog watches";
  EXPECT_LT(2 * o.hovered, o.longer) << "a watchdog saw the model's link instead of the real states";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "real_link");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
