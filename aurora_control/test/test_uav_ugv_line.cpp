// AuRoRA's UAV-UGV line (docs/formation.md, "The UAV-UGV line"): a Pioneer
// P3-DX leading an AR.Drone, the spherical variables and the law without
// integration, flown from the shipped files (config/formations/
// line_pioneer_ardrone*.yaml). Its first tick and the states after one
// step, each robot on its own law and model at 1/30 s, equal the values the
// spec computed with AuRoRA's own code (the Pioneer's acceleration over
// 0.1 s, its control point put at (-1, 0)); the whole run tracks as
// AuRoRA's; a bad file is refused naming the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/uav_ugv/uav_ugv_yaml.h"
#include "aurora_control/law/ardrone2/control_law.h"
#include "aurora_control/law/pioneer3dx/pioneer_laws.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "edited_file.h"
#include "yaml-cpp/yaml.h"

namespace {

using UavUgv = aurora_control::UavUgvLine<double>;

void expectNearRelative(const double* got, const std::vector<double>& want, double rel, const char* what) {
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i], want[i], rel * (1.0 + std::fabs(want[i]))) << what << " [" << i << "]";
  }
}

using Tick = aurora_control::FormationObservation<double, aurora_control::UavUgvShape,
                                                  aurora_control::UavUgvRobots::Data>;

// The standard scenario from its shipped file (the original's kinematic
// pairing from line_pioneer_ardrone_kinematic.yaml), flown `ticks` ticks
// through the one formation loop, `at(o)` after each: o.X_before the
// robots' states at its start, o.drones[r].model.X after their steps.
template <class At>
void flyScenario(bool kinematic_pioneer, long ticks, At&& at) {
  const std::string config = AURORA_CONFIG_DIR;
  const std::string file = config + "/formations/line_pioneer_ardrone" + (kinematic_pioneer ? "_kinematic" : "") + ".yaml";
  const aurora_control::UavUgvRun run = aurora_control::uavUgvRun(aurora_control::readUavUgvLineFile(file, config));
  const long ran = aurora_control::runFormation<aurora_control::UavUgvRobots, double, aurora_control::UavUgvShape,
                                                aurora_control::kDelayHistory>(run, ticks, at);
  EXPECT_EQ(ran, ticks);
}

}  // namespace

TEST(UavUgvLine, TheFirstTickIsAuRoRAs) {
  flyScenario(false, 1, [](const Tick& f) {
    EXPECT_TRUE(f.layer_ran);
    const double tol = 1e-9;  // the spec prints 10 digits at k = 0
    expectNearRelative(f.layer.Q(), {-1, 0, 0, 1.25, 0, 0.6435011088}, tol, "Q");
    expectNearRelative(f.layer.Qtil(), {1, 0, 0, 0.75, 1.570796327, 0.4036964424}, tol, "Q~");
    expectNearRelative(f.layer.velocity(0), {0.1397343957, 0.1, 0}, tol, "dXr of the Pioneer");
    expectNearRelative(f.layer.velocity(1), {0.140987219, 0.109836913, 0.0102748155}, tol, "dXr of the drone");
    expectNearRelative(f.layer.position(1), {6.1e-17, 1, 1.732050808}, tol, "the drone's desired position");
    expectNearRelative(f.steps[0].U, {0.3736396088, 0.7097933116}, tol, "the Pioneer's Ud");
    const double* U_drone = f.steps[1].U;
    EXPECT_NEAR(U_drone[aurora_sim::kUClimb], 0.8810137624, tol);
    for (int i : {aurora_sim::kURoll, aurora_sim::kUPitch, aurora_sim::kUYawRate}) EXPECT_NEAR(U_drone[i], 0.0, 1e-9);
    // k = 1: the corrected dynamic Pioneer and the drone after one step each.
    const double rel = 1e-12;
    const double *pioneer = f.drones[0].model.X, *drone = f.drones[1].model.X;
    expectNearRelative(pioneer + aurora_sim::kPioneerU, {0.02333205999780124, 0.10913181297804046}, rel, "Pioneer U");
    const double pose[3] = {pioneer[aurora_sim::kX], pioneer[aurora_sim::kY], pioneer[aurora_sim::kYaw]};
    expectNearRelative(pose, {-0.9992222646667399, 0.0005456590648902024, 0.0036377270992680156}, rel, "Pioneer pose");
    EXPECT_NEAR(drone[aurora_sim::kZ], 0.7458057587350768, rel);
  });
}

// The original script's own pairing: the kinematic Pioneer (U = Ud).
TEST(UavUgvLine, TheKinematicPioneersFirstStepIsAuRoRAs) {
  flyScenario(true, 1, [](const Tick& f) {
    const double *pioneer = f.drones[0].model.X, *drone = f.drones[1].model.X;
    const double pose[3] = {pioneer[aurora_sim::kX], pioneer[aurora_sim::kY], pioneer[aurora_sim::kYaw]};
    expectNearRelative(pose, {-0.9875453463731737, 0.0035489665580458753, 0.02365977705363917}, 1e-12, "Pioneer pose");
    EXPECT_NEAR(drone[aurora_sim::kZ], 0.7458057587350768, 1e-12);
  });
}

// The whole run (k = 0 .. 3899, t < 130 s), RMS after 20 s, as the spec
// measured AuRoRA's code: xf, yf 0.0069 m, rho 0.0039 m, alpha 0.0071 rad,
// beta 0.0034 rad, the drone's position error 0.013 m, the closest
// approach 1.24 m (dynamic Pioneer); 0.0093, 0.0093, 0.0080, 0.0080, 0.014,
// 1.21 (kinematic).
TEST(UavUgvLine, TheStandardScenarioTracksAsAuRoRAs) {
  for (bool kinematic : {false, true}) {
    SCOPED_TRACE(kinematic ? "kinematic Pioneer" : "dynamic Pioneer");
    double sq[5] = {0, 0, 0, 0, 0}, closest = 1e9;
    long n = 0;
    flyScenario(kinematic, 3900, [&](const Tick& f) {
      const double *pioneer = f.drones[0].model.X, *drone = f.drones[1].model.X;  // after the tick's steps
      const double* e = f.layer.Qtil();
      double d[3];
      for (int i = 0; i < 3; ++i) d[i] = drone[i] - pioneer[i];
      closest = std::min(closest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      if (double(f.k) / 30.0 < 20.0) return;
      const double* Xd = f.layer.position(1);  // the drone's desired position of this tick
      double de[3];
      for (int i = 0; i < 3; ++i) de[i] = Xd[i] - drone[i];
      sq[0] += e[0] * e[0] + e[1] * e[1], sq[1] += e[3] * e[3], sq[2] += e[4] * e[4], sq[3] += e[5] * e[5];
      sq[4] += de[0] * de[0] + de[1] * de[1] + de[2] * de[2];
      ++n;
    });
    double rms[5];
    for (int i = 0; i < 5; ++i) rms[i] = std::sqrt(sq[i] / double(n));
    const std::vector<double> spec = kinematic ? std::vector<double>{0.0093, 0.0093, 0.0080, 0.0080, 0.014}
                                               : std::vector<double>{0.0069, 0.0039, 0.0071, 0.0034, 0.013};
    const char* names[5] = {"xf, yf", "rho", "alpha", "beta", "drone"};
    std::fprintf(stderr, "%s Pioneer: RMS after 20 s xf,yf %.4f m, rho %.4f m, alpha %.4f, beta %.4f rad, drone %.4f m; "
                 "closest %.3f m\n", kinematic ? "kinematic" : "dynamic", rms[0], rms[1], rms[2], rms[3], rms[4], closest);
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(rms[i], spec[i], 0.05 * spec[i]) << names[i];  // the spec rounds to 2 digits
    EXPECT_NEAR(closest, kinematic ? 1.21 : 1.24, 0.005);
  }
}

// Check 5 (docs/formation.md, "Formation checks"): the Pioneer's commands as
// it applies them, against real_ground.yaml's limits (the study's
// defaults); the drone is no ground robot. The standard scenario holds it
// with its largest share; a speed limit below what the Pioneer is sent
// fails it, and only it.
TEST(UavUgvLine, CheckFiveJudgesTheGroundRobotsCommands) {
  using Judge = aurora_control::FormationJudge<double, aurora_control::UavUgvShape, aurora_control::UavUgvRobots::Data>;
  using Ground = aurora_control::GroundCommands<aurora_control::UavUgvRobots::Vehicle>;
  const YAML::Node safety = YAML::LoadFile(std::string(AURORA_CONFIG_DIR) + "/safety/real_ground.yaml")["safety"];
  auto study = aurora_control::FormationCriteria<double>::study();
  EXPECT_EQ(study.max_ground_speed, safety["max_speed"].as<double>());
  EXPECT_EQ(study.max_ground_turn_rate, safety["max_turn_rate"].as<double>());
  bool ground[2] = {false, false};
  const auto judged = [&](const aurora_control::FormationCriteria<double>& criteria, double& share) {
    Judge judge{criteria, false, 1.0 / 30.0, {}, {}};
    judge.metrics.reset();
    share = 0.0;
    flyScenario(false, 3900, [&](const Tick& o) {
      judge(o);
      const double* U = o.steps[0].U;
      share = std::max({share, std::fabs(U[0]) / criteria.max_ground_speed, std::fabs(U[1]) / criteria.max_ground_turn_rate});
      double speed, turn_rate;
      for (int r = 0; r < 2; ++r) ground[r] = Ground::of(o.params[r].model, o.steps[r].U, speed, turn_rate);
    });
    return judge.metrics;
  };
  double share;
  const auto held = judged(study, share);
  EXPECT_TRUE(ground[0]);
  EXPECT_FALSE(ground[1]);
  EXPECT_DOUBLE_EQ(held.ground_command, share);
  EXPECT_NEAR(share, 0.7531, 1e-4);  // its largest u_ref, 0.3765 m/s (tick 5), of 0.5 m/s
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(held.ok[i]) << "check " << i + 1;
  EXPECT_TRUE(held.feasible());
  study.max_ground_speed = 0.37;
  const auto failed = judged(study, share);
  EXPECT_DOUBLE_EQ(failed.ground_command, share);
  EXPECT_GT(share, 1.0);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(failed.ok[i]) << "check " << i + 1;
  EXPECT_FALSE(failed.ok[4]);
  EXPECT_FALSE(failed.feasible());
}

// The variables and their inverse are proper inverses for rho > 0; a
// vertical line has alpha = atan2(0, 0) = 0.
TEST(UavUgvLine, TheVariablesAndTheirInverse) {
  const double Q[6] = {0.3, -0.4, 0.0, 2.0, 2.5, -0.4};
  double X[6], back[6];
  UavUgv::positions(Q, X);
  UavUgv::variables(X, back);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], Q[i], 1e-14) << i;
  const double vertical[6] = {0, 0, 0, 0, 0, 2};
  UavUgv::variables(vertical, back);
  EXPECT_EQ(back[4], 0.0);
  EXPECT_NEAR(back[5], M_PI / 2, 1e-15);
}

namespace {

// The refusal of the shipped file with `from` replaced by `to` ("" when it loads).
std::string refusalOfEdited(const std::string& from, const std::string& to) {
  return aurora_tests::refusalOfEditedFile("formations/line_pioneer_ardrone.yaml", from, to,
                                           [](const std::string& path, const std::string& config) {
                                             aurora_control::readUavUgvLineFile(path, config);
                                           });
}

}  // namespace

TEST(UavUgvLine, ABadFileIsRefusedNamingTheKey) {
  EXPECT_EQ(refusalOfEdited("start: [-1.0, 0.0, 0.0]", "start: [-1.0, 0.0, 0.0]"), "");
  std::string e = refusalOfEdited("start: [-1.0, 0.0, 0.0]", "start: [-1.0, 0.0, 0.5]");
  EXPECT_NE(e.find("'formation.robots[0].start' = [-1, 0, 0.5] has z = 0.5 m: accepted z = 0"), std::string::npos) << e;
  e = refusalOfEdited("start: [0.0, 0.0, 0.75]", "start: [0.0, 0.0, -1.0]");
  EXPECT_NE(e.find("'formation.robots[1].start' = [0, 0, -1] has z = -1 m, below the ground: accepted heights [0, 100] m"),
            std::string::npos) << e;
  e = refusalOfEdited("    - vehicle: vehicles/ardrone2.yaml", "    - namespace: bebop2\n      vehicle: vehicles/ardrone2.yaml");
  EXPECT_NE(e.find("'formation.robots[0].namespace' is missing: name both robots' namespaces or neither"),
            std::string::npos) << e;
  e = refusalOfEdited("duration: 130", "duration: 5");
  EXPECT_NE(e.find("'formation.duration' = 5 s is refused: the formation checks judge a flight from 10 s on"),
            std::string::npos) << e;
  e = refusalOfEdited("name: pioneer_dynamic", "name: pioneer_kinematic");
  EXPECT_NE(e.find("'formation.robots[0].controller.name' = 'pioneer_kinematic' is refused: this robot flies "
                   "pioneer_dynamic"), std::string::npos) << e;
  e = refusalOfEdited("kd2: [0.12, 0.035]", "kd2: [0.12, -0.035]");
  EXPECT_NE(e.find("'formation.robots[0].controller.kd2' must be a list of 2 numbers in [0, 10]"), std::string::npos)
      << e;
  e = refusalOfEdited("- vehicle: vehicles/ardrone2.yaml", "- vehicle: vehicles/bebop2.yaml");
  EXPECT_NE(e.find("is of type 'bebop2', but the UAV-UGV line's robot 2 flies type 'ardrone2'"), std::string::npos) << e;
  e = refusalOfEdited("tick: 0.03333333333333333", "tick: 0");
  EXPECT_NE(e.find("'formation.tick' = 0 is outside the accepted range (0, 1] s"), std::string::npos) << e;
  e = refusalOfEdited("start: [0.0, 0.0, 0.75]", "start: [-1.0, 0.0, 0.0]");
  EXPECT_NE(e.find("'formation.robots[1].start' is robot 1's: rho = 0"), std::string::npos) << e;
  e = refusalOfEdited("  duration: 130", "  duration: 130\n  period: 0.2");
  EXPECT_NE(e.find("'formation.period' is not a known key"), std::string::npos) << e;
}
