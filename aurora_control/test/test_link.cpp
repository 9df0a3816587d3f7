// The link model (link.h, loop_link.h; docs/links.md): the worked timeline,
// the draws' distributions, the refusals of link files, and an ideal link
// through the model equal to today's loop bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "aurora_control/loop/ardrone2/ardrone_study.h"
#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/loop/flight_runner.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/loop/loop_link.h"
#include "aurora_sim/vehicle/ardrone2/ardrone_params.h"

using namespace aurora_control;

// The AR.Drone's laws' settings and controller core (their family, other_laws.h).
using ControllerSettings = aurora_control::LawSettings<aurora_control::ArdroneLawData>;
template <int Capacity>
using ArdroneController = aurora_control::DelayedController<Capacity, ControllerSettings>;

namespace {

// The arrivals the channel decides for steps 0..n-1 of one direction.
std::vector<long> received(const LinkDirection& d, long n, uint32_t seed = 7) {
  LinkChannel<64> c;
  std::vector<long> out;
  for (long k = 0; k < n; ++k) {
    c.send(d, LossRule::of(d), packetDraws(seed, 0, LinkDirectionId::kUplink, k), k);
    out.push_back(c.receive(d, k));
  }
  return out;
}

std::string linkRefusal(const std::string& yaml) {
  try {
    readLink(YamlReader(), YAML::Load(yaml), "link");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Link, ConstantDelayIsTheDelayRule) {
  LinkDirection d;
  d.delay = 3;
  const std::vector<long> got = received(d, 8);
  const std::vector<long> want{-1, -1, -1, 0, 1, 2, 3, 4};  // none arrived yet, then k - 3
  EXPECT_EQ(got, want);
}

// The receive rule (docs/links.md, "What the receiver uses") against a
// brute force over the same draws: at step k the newest-sent packet among all
// that arrived by k, never going back to an older one.
TEST(Link, ReceiveIsTheNewestArrivedPacketNeverAnOlderOne) {
  LinkDirection d;
  d.delay = 2;
  d.jitter = JitterKind::kGeometric;
  d.jitter_mean = 1.5;
  d.jitter_max = 6;
  d.loss = 0.2;
  d.burst = 3;
  const long n = 3000;
  std::vector<long> arrival(n);
  bool lost = false;
  for (long j = 0; j < n; ++j) {
    const PacketDraws u = packetDraws(7, 0, LinkDirectionId::kUplink, j);
    lost = packetLost(d, lost, u.lossU());
    arrival[j] = lost ? -1 : j + d.delay + jitterSamples(d, u.jitterU());
  }
  const std::vector<long> got = received(d, n);
  long newest = -1, differ = 0;
  for (long k = 0; k < n; ++k) {
    long best = -1;
    for (long j = 0; j <= k; ++j) {
      if (arrival[j] >= 0 && arrival[j] <= k) best = j;
    }
    newest = best > newest ? best : newest;
    differ += got[k] != newest;
  }
  EXPECT_EQ(differ, 0);
  // Not a vacuous case: some packets were lost and some overtaken.
  long losses = 0, overtaken = 0;
  for (long j = 0; j + 1 < n; ++j) losses += arrival[j] < 0, overtaken += arrival[j] > arrival[j + 1] && arrival[j + 1] >= 0;
  EXPECT_GT(losses, 100);
  EXPECT_GT(overtaken, 100);
}

TEST(Link, JitterDrawsFollowTheirFormulas) {
  LinkDirection u;
  u.jitter = JitterKind::kUniform;
  u.jitter_max = 3;
  EXPECT_EQ(jitterSamples(u, 0.0001), 0);
  EXPECT_EQ(jitterSamples(u, 0.9999), 3);
  EXPECT_EQ(jitterSamples(u, 0.5), 2);  // floor(0.5 * 4)
  LinkDirection g;
  g.jitter = JitterKind::kGeometric;
  g.jitter_mean = 2.0;
  g.jitter_max = 1000;
  double sum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) sum += jitterSamples(g, packetDraws(3, 0, LinkDirectionId::kUplink, i).jitterU());
  EXPECT_NEAR(sum / n, 2.0, 0.03);  // the mean before a cut that never bites
  g.jitter_max = 4;
  EXPECT_EQ(jitterSamples(g, 0.999999), 4);  // the cut
}

// The channels' integer forms (uniformJitter, LossRule) equal the documented
// formulas in doubles word for word: at the words around every threshold
// and at a million drawn words.
TEST(Link, IntegerRulesAreTheDocumentedFormulas) {
  std::vector<uint32_t> words = {0u, 1u, 2u, 0x7fffffffu, 0x80000000u, 0xfffffffeu, 0xffffffffu};
  for (uint64_t i = 0; i < 1000000; ++i) words.push_back(packetDraws(5, i, LinkDirectionId::kUplink, i).loss_w);
  long checked = 0;
  for (const double loss : {0.01, 0.05, 0.1, 0.3, 0.5, 0.7, 0.99, 1.0 / 3.0}) {
    for (const double burst : {1.0, 1.5, 3.0, 20.0}) {
      LinkDirection d;
      d.loss = loss, d.burst = burst;
      if (burst > 1.0 && loss > burst / (burst + 1.0)) continue;
      const LossRule rule = LossRule::of(d);
      std::vector<uint32_t> near = words;
      for (const uint64_t t : {rule.good, rule.bad}) {
        for (int64_t o = -2; o <= 2; ++o) {
          if (int64_t(t) + o >= 0 && int64_t(t) + o <= 0xffffffffLL) near.push_back(static_cast<uint32_t>(int64_t(t) + o));
        }
      }
      for (const uint32_t w : near) {
        for (const bool before : {false, true}) {
          ASSERT_EQ(rule.lost(before, w), packetLost(d, before, unitFromBits(w))) << loss << " " << burst << " " << w;
          ++checked;
        }
      }
    }
  }
  for (const long max : {0L, 1L, 3L, 6L, 300L, 2047L}) {
    LinkDirection d;
    d.jitter = JitterKind::kUniform, d.jitter_max = max;
    for (const uint32_t w : words) {
      ASSERT_EQ(uniformJitter(w, max), jitterSamples(d, unitFromBits(w))) << max << " " << w;
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000000);
}

TEST(Link, LossShareAndBurstLengthAreTheConfiguredOnes) {
  for (double burst : {1.0, 5.0}) {
    LinkDirection d;
    d.loss = 0.1;
    d.burst = burst;
    bool lost = false;
    long losses = 0, runs = 0;
    const long n = 400000;
    for (long k = 0; k < n; ++k) {
      const bool now = packetLost(d, lost, packetDraws(11, 2, LinkDirectionId::kDownlink, k).lossU());
      losses += now, runs += now && !lost;
      lost = now;
    }
    EXPECT_NEAR(double(losses) / n, 0.1, 0.005) << "burst " << burst;
    // Mean run of losses: 1 / (1 - loss) for independent losses, `burst` for the chain.
    EXPECT_NEAR(double(losses) / runs, burst > 1 ? burst : 1.0 / 0.9, 0.15) << "burst " << burst;
  }
}

TEST(Link, DrawsArePureFunctionsOfTheirKey) {
  const PacketDraws a = packetDraws(1, 5, LinkDirectionId::kUplink, 9);
  const PacketDraws b = packetDraws(1, 5, LinkDirectionId::kUplink, 9);
  EXPECT_EQ(a.jitterU(), b.jitterU());
  EXPECT_EQ(a.lossU(), b.lossU());
  EXPECT_NE(a.lossU(), packetDraws(1, 5, LinkDirectionId::kDownlink, 9).lossU());
  EXPECT_NE(a.lossU(), packetDraws(1, 6, LinkDirectionId::kUplink, 9).lossU());
  EXPECT_NE(a.lossU(), packetDraws(2, 5, LinkDirectionId::kUplink, 9).lossU());
}

TEST(Link, DroneHoversUntilTheFirstCommandArrives) {
  LinkParams link;
  link.downlink.delay = 2;
  link.downlink.loss = 0.0;
  ModelLink<64, double> m(link, 0, 0, 1.0 / 30.0);
  const double sent[4] = {0.5, -0.5, 0.25, 0.1};
  double got[4];
  m.downlink(0, sent, got);
  EXPECT_EQ(got[0], 0.0);  // nothing arrived yet: hover
  m.downlink(1, sent, got);
  EXPECT_EQ(got[0], 0.0);
  m.downlink(2, sent, got);
  EXPECT_EQ(got[0], 0.5);  // step 0's command, two steps late
}

// cmd_timeout 0.2 s at 30 Hz: 6 steps without a new command and the drone
// hovers; a new one ends it.
TEST(Link, DroneHoversWhenTheNewestCommandIsTooOld) {
  LinkParams link;
  link.downlink.loss = 0.5;
  link.downlink.burst = 30;
  ModelLink<64, double> m(link, 0, 0, 1.0 / 30.0);
  const double sent[4] = {0.5, -0.5, 0.25, 0.1};
  long hovered = 0, flown = 0, wrong = 0;
  for (long k = 0; k < 5000; ++k) {
    double got[4];
    m.downlink(k, sent, got);
    const long age = m.downlinkChannel().sinceArrival(k);
    const bool should_hover = age < 0 || age >= 6;
    wrong += should_hover != (got[0] == 0.0);
    hovered += got[0] == 0.0, flown += got[0] != 0.0;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(hovered, 500);  // bursts of 30 lost commands on average
  EXPECT_GT(flown, 500);
}

TEST(Link, AnIdealLinkThroughTheModelIsTodaysLoopBitForBit) {
  const auto p = aurora_sim::referenceArdrone2Params();
  ControllerSettings set;
  set.law = int(LawType::kPdSaturated);
  set.gains.pd = {0.5, 0.85};
  set.vehicle = p;
  set.delay = 7;
  Task<double> task = positioningTask(2.0, 1.0, 2.0, 20.0);
  std::vector<double> ideal, model;
  runFlight(p, set, task, 601, [&](const FlightObservation& o, double) {
    ideal.insert(ideal.end(), o.after.model.X, o.after.model.X + 12);
  });
  // The same through ModelLink: a loss of 0 with a seed is not ideal() (a
  // lossy link's code path) yet draws nothing that changes the arrivals.
  set.link.seed = 99;
  set.link.uplink.jitter = JitterKind::kUniform;  // max 0: the model path, no jitter
  ASSERT_FALSE(set.link.ideal());
  runFlight(p, set, task, 601, [&](const FlightObservation& o, double) {
    model.insert(model.end(), o.after.model.X, o.after.model.X + 12);
  });
  ASSERT_EQ(ideal.size(), model.size());
  long differ = 0;
  for (size_t i = 0; i < ideal.size(); ++i) differ += ideal[i] != model[i];
  EXPECT_EQ(differ, 0);
}

TEST(Link, ALossyLinkChangesTheFlightAndIsRepeatable) {
  const auto p = aurora_sim::referenceArdrone2Params();
  ControllerSettings set;
  set.gains.pd = {0.5, 0.85};
  set.vehicle = p;
  Task<double> task = positioningTask(2.0, 1.0, 2.0, 20.0);
  set.link = readLinkFile(std::string(AURORA_CONFIG_DIR) + "/links/wifi_congested.yaml");
  set.delay = set.link.uplink.delay;
  const FlightResult a = runFlight(p, set, task, 601, [](const FlightObservation&, double) {});
  const FlightResult b = runFlight(p, set, task, 601, [](const FlightObservation&, double) {});
  EXPECT_EQ(a.itae, b.itae);
  set.link = LinkParams();
  const FlightResult ideal = runFlight(p, set, task, 601, [](const FlightObservation&, double) {});
  EXPECT_NE(a.itae, ideal.itae);
}

TEST(LinkFile, MistakesAreRefusedNamingTheKey) {
  EXPECT_NE(linkRefusal("uplink: {loss: 1.0}").find("'link.uplink.loss' = 1 is outside the accepted range [0, 0.99]"),
            std::string::npos);
  EXPECT_NE(linkRefusal("uplink: {loss: -0.1}").find("'link.uplink.loss' = -0.1"), std::string::npos);
  EXPECT_NE(linkRefusal("downlink: {burst: 0.5}")
                .find("'link.downlink.burst' = 0.5 is outside the accepted range [1, 1000]"),
            std::string::npos);
  EXPECT_NE(linkRefusal("uplink: {delay: -2}").find("'link.uplink.delay' = -2 is refused"), std::string::npos);
  EXPECT_NE(linkRefusal("uplink: {delay: 2000, jitter: {kind: uniform, max: 100}}").find("beyond the history"),
            std::string::npos);
  EXPECT_NE(linkRefusal("uplink: {delay: 1, lag: 2}").find("'link.uplink.lag' is not a known key"), std::string::npos);
  EXPECT_NE(linkRefusal("uplink: {jitter: {kind: gauss, max: 2}}").find("accepted uniform, geometric"),
            std::string::npos);
  EXPECT_NE(linkRefusal("uplink: {loss: 0.9, burst: 2}").find("accepted up to burst / (burst + 1)"), std::string::npos);
  EXPECT_EQ(linkRefusal("uplink: {delay: 2, jitter: {kind: geometric, mean: 1, max: 6}, loss: 0.05, burst: 20}"), "");
}

TEST(LinkFile, ShippedPresetsLoad) {
  for (const char* name : {"ideal", "tum_ardrone", "wifi_lab", "wifi_congested"}) {
    const LinkParams l = readLinkFile(std::string(AURORA_CONFIG_DIR) + "/links/" + name + ".yaml");
    EXPECT_EQ(l.ideal(), std::string(name) == "ideal") << name;
  }
}

// The node's incremental form (DelayedController over NodeLink) gives the
// offline runner's drone commands at every step over a lossy, jittery link:
// fed the runner's states one step at a time, as the lockstep sim sends them.
TEST(Link, TheNodesCoreOverALinkIsTheRunners) {
  const auto p = aurora_sim::referenceArdrone2Params();
  ControllerSettings set;
  set.gains.pd = {0.5, 0.85};
  set.vehicle = p;
  set.Ts = p.Ts;
  set.link = readLinkFile(std::string(AURORA_CONFIG_DIR) + "/links/wifi_congested.yaml");
  set.delay = set.link.uplink.delay;
  const Task<double> task = positioningTask(2.0, 1.0, 2.0, 30.0);
  std::unique_ptr<ArdroneController<kDelayHistory>> node(new ArdroneController<kDelayHistory>());
  node->settings = set;
  node->configureLink();
  long differ = 0, hovered = 0;
  const FlightResult r = runFlight(p, set, task, 901, [&](const FlightObservation& o, double) {
    StateSample s;
    s.step = o.k;
    for (int i = 0; i < aurora_sim::kStateSize; ++i) s.X[i] = o.X_before[i];
    node->push(s);
    const ControlOutput out = node->compute(task.at(taskTime(o.k, p.Ts)));
    for (int i = 0; i < 4; ++i) differ += aurora_common::clampUnit(out.U[i]) != o.step.U[i];
    hovered += out.drone_hovers;
  });
  EXPECT_EQ(differ, 0);
  EXPECT_GT(hovered, 10);  // the link made the drone hover now and then
  EXPECT_EQ(node->compute(task.at(taskTime(900, p.Ts))).itae, r.itae);
}

// Through a loss burst longer than the node's history the law keeps the
// last state its link delivered (as the sweep's StateHistory does), not the
// newest state, which the link lost.
TEST(Link, ALossBurstLongerThanTheNodesHistoryKeepsTheLastStateDelivered) {
  constexpr int kShort = 64;
  ControllerSettings set;
  set.vehicle = aurora_sim::referenceArdrone2Params();
  set.Ts = set.vehicle.Ts;
  set.link.uplink.loss = 0.5;
  set.link.uplink.burst = 300.0;
  set.link.seed = 7;
  std::unique_ptr<ArdroneController<kShort>> node(new ArdroneController<kShort>());
  node->settings = set;
  node->configureLink();
  const double desired[3] = {1.0, 1.0, 1.0};
  long delivered = -1, burst = 0, longest = 0, checked = 0;
  for (long k = 0; k < 3000; ++k) {
    StateSample s;
    s.step = k;
    node->push(s);
    const ControlOutput out = node->compute(desired);
    if (out.state_arrived) delivered = k, burst = 0;
    else longest = std::max(longest, ++burst);
    if (delivered < 0) continue;
    EXPECT_EQ(out.used->step, delivered) << "step " << k << ", " << burst << " states lost in a row";
    checked += burst > kShort;
  }
  EXPECT_GT(longest, kShort);  // the seed gives bursts longer than the history
  EXPECT_GT(checked, 0);
}
