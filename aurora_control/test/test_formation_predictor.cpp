// Issue 51 (1): formation robots fly the predictor their controller file
// gives (docs/predictor.md, "Formations"), in the offline runner and the
// formation node's core alike. With the exact model (the nominal vehicle
// the plant is) `resimulate` predicts the present to the bit, so a delayed
// formation flies as the undelayed one: a delay that shows proves the
// predictor was dropped.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_controller.h"
#include "aurora_control/formation/line/line_yaml.h"
#include "aurora_control/formation/triangle/triangle_yaml.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "config_dir.h"

namespace {

using namespace aurora_control;
using Line = LineFormation<double>;
using Underactuated = ArdroneLaw<LawType::kUnderactuated>;

using aurora_tests::kConfig;

// Every robot's state before each tick (X_k), in order.
template <class Shape>
struct Trajectory {
  std::vector<double> X;
  void operator()(const FormationObservation<double, Shape, aurora_control::ArdroneLawData>& o) {
    for (int d = 0; d < Shape::kDrones; ++d) X.insert(X.end(), o.X_before[d], o.X_before[d] + 12);
  }
};

TriangleRun<TriangleDroneLaw> triangle(const std::string& file, long delay) {
  TriangleSetup s = readTriangleFile(kConfig + "/formations/" + file, kConfig);
  for (long& d : s.delay) d = delay;
  return triangleRun<TriangleDroneLaw>(s);
}

template <class Shape, class Run>
std::vector<double> flown(const Run& run, long ticks) {
  Trajectory<Shape> t;
  runFormation<Underactuated, double, Shape, kShortHistory>(run, ticks, t);
  return t.X;
}

TEST(FormationPredictor, TheTrianglesDronesFlyTheirControllerFilesPredictor) {
  const TriangleRun<TriangleDroneLaw> with = triangle("triangle_ardrones_predictor.yaml", 6);
  for (int d = 0; d < 3; ++d) {
    EXPECT_EQ(with.drone[d].predictor.form, PredictorForm::kResimulate) << "drone " << d + 1;
    EXPECT_EQ(triangle("triangle_ardrones.yaml", 6).drone[d].predictor.form, PredictorForm::kOff);
  }
  const long ticks = 900;
  const std::vector<double> undelayed = flown<Triangle>(triangle("triangle_ardrones.yaml", 0), ticks);
  const std::vector<double> delayed = flown<Triangle>(triangle("triangle_ardrones.yaml", 6), ticks);
  ASSERT_NE(undelayed, delayed) << "6 samples of delay changed nothing: no test of the predictor";
  EXPECT_EQ(flown<Triangle>(with, ticks), undelayed) << "the predictor over the exact model cancels the delay";
  EXPECT_EQ(flown<Triangle>(triangle("triangle_ardrones_predictor.yaml", 0), ticks), undelayed)
      << "at delay 0 the predictor is the received state";
}

// The two-drone line: each drone's controller file, each its own delay,
// over links (drone 2's jittery and lossy: the predictor anchors on late
// and lost states too), and a command delay on drone 1's downlink.
LineRun line(bool predictor, long delay_1, long delay_2, bool links) {
  std::string text;
  {
    FILE* f = std::fopen((kConfig + "/formations/line_lemniscate_ik.yaml").c_str(), "r");
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
  }
  // Its drones on the shipped controller files (the same gains, with and without the predictor).
  const std::string controller = predictor ? "controllers/underactuated_predictor.yaml" : "controllers/underactuated.yaml";
  text = text.substr(0, text.find("  drones:")) + "  drones:\n" +
         "    - {namespace: ardrone1, start: [-1.0, 0.0, 0.75], controller: " + controller + "}\n" +
         "    - {namespace: ardrone2, start: [1.0, 0.0, 1.0], controller: " + controller + "}\n";
  const std::string path = ::testing::TempDir() + "/line_predictor.yaml";
  FILE* out = std::fopen(path.c_str(), "w");
  std::fputs(text.c_str(), out);
  std::fclose(out);
  FormationFile file = readFormationFile(path, kConfig);
  if (links) {
    file.drones[0].link = readLinkFile(kConfig + "/links/ideal.yaml");
    file.drones[0].link.downlink.delay = 2;
    file.drones[1].link = readLinkFile(kConfig + "/links/wifi_congested.yaml");
  }
  file.drones[0].delay = delay_1, file.drones[1].delay = delay_2;
  if (links) file.drones[0].link.uplink.delay = delay_1, file.drones[1].link.uplink.delay = delay_2;
  return formationRun(file, aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(kConfig + "/vehicles/ardrone2.yaml"));
}

TEST(FormationPredictor, TheLinesDronesFlyTheirControllerFilesPredictor) {
  const LineRun with = line(true, 4, 9, false);
  EXPECT_EQ(with.drone[0].predictor.form, PredictorForm::kResimulate);
  EXPECT_EQ(with.drone[1].predictor.form, PredictorForm::kResimulate);
  const long ticks = 1200;
  const std::vector<double> undelayed = flown<Line>(line(false, 0, 0, false), ticks);
  ASSERT_NE(flown<Line>(line(false, 4, 9, false), ticks), undelayed);
  EXPECT_EQ(flown<Line>(with, ticks), undelayed);
}

// Over links the loop differs from the undelayed one (losses hold old
// states, the downlink's delay is the predictor's command delay): the
// predictor's errors are smaller than the plain law's.
TEST(FormationPredictor, OverLinksThePredictorStaysCloserToTheUndelayedFlight) {
  const long ticks = 1500;
  const std::vector<double> undelayed = flown<Line>(line(false, 0, 0, false), ticks);
  const auto distance = [&](const std::vector<double>& X) {
    double worst = 0.0;
    for (size_t i = 0; i < X.size(); ++i) worst = std::max(worst, std::fabs(X[i] - undelayed[i]));
    return worst;
  };
  const double plain = distance(flown<Line>(line(false, 4, 9, true), ticks));
  const double predicted = distance(flown<Line>(line(true, 4, 9, true), ticks));
  EXPECT_LT(predicted, 0.5 * plain) << "plain " << plain << ", predicted " << predicted;
}

// The formation node's core answers every tick with the runner's commands
// and layer, bit for bit, with the predictor on each drone over its link.
TEST(FormationPredictor, TheNodesCoreIsTheRunnersTick) {
  const LineRun run = line(true, 3, 7, true);
  struct Tick {
    double X[2][12], U[2][4], Q[6];
  };
  std::vector<Tick> offline;
  auto observe = [&](const LineObservation& o) {
    Tick t;
    for (int d = 0; d < 2; ++d) {
      std::memcpy(t.X[d], o.X_before[d], sizeof t.X[d]);
      std::memcpy(t.U[d], o.steps[d].U, sizeof t.U[d]);
    }
    std::memcpy(t.Q, o.layer.Q(), sizeof t.Q);
    offline.push_back(t);
  };
  const long ticks = 900;
  runFormation<Underactuated, double, Line, kShortHistory>(run, ticks, observe);
  FormationController<kShortHistory, aurora_control::LineFormation<double>, aurora_control::LawSettings<aurora_control::ArdroneLawData>> core(run, aurora_control::LawSettings<aurora_control::ArdroneLawData>::flying<aurora_control::ArdroneLaw<LawType::kUnderactuated>>());
  long mismatches = 0, predicted = 0;
  for (long k = 0; k < ticks; ++k) {
    for (int d = 0; d < 2; ++d) {
      StateSample s;
      s.step = k;
      std::memcpy(s.X, offline[k].X[d], sizeof offline[k].X[d]);
      ASSERT_TRUE(core.push(d, s));
    }
    const auto t = core.tick(k);
    for (int d = 0; d < 2; ++d) {
      mismatches += std::memcmp(t.out[d].U, offline[k].U[d], sizeof offline[k].U[d]) != 0;
      predicted += t.out[d].predicted;
    }
    mismatches += std::memcmp(core.layer().Q(), offline[k].Q, sizeof offline[k].Q) != 0;
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(predicted, 2 * ticks);
}

}  // namespace
