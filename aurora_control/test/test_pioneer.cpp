// The Pioneer P3-DX (docs/pioneer3dx.md): its model and laws against the
// values the spec computed with AuRoRA's own code, its vehicle file, and the
// spec's lemniscate flown with the dynamic controller on the dynamic model.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "aurora_control/law/pioneer3dx/pioneer_laws.h"
#include "aurora_control/law/pioneer3dx/pioneer_yaml.h"
#include "aurora_control/loop/flight_setup.h"
#include "aurora_sim/vehicle/pioneer3dx/pioneer3dx_profile.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "edited_file.h"

namespace {

// The Pioneer's sample time [s], which its laws' file reader is given
// (readLawFile; they run every model step and read none).
constexpr double kPioneerTs = 0.1;

using aurora_control::PioneerDynamic;
using aurora_control::PioneerKinematic;
using aurora_control::Reference;
using aurora_sim::Pioneer3dx;

// The spec's start: a new robot put at the origin, heading 0 (its control
// point at (a, 0)), at rest: the vehicle's start, as every loop's.
Pioneer3dx::State<double> start(const Pioneer3dx::Params<double>& p) {
  Pioneer3dx::State<double> s;
  Pioneer3dx::start(p, s);
  return s;
}

// The lemniscate of AuRoRA's TestPioneer3D: x = sin(wt), y = sin(2wt), w = 0.1.
Reference<double> lemniscate(double t) {
  const double w = 0.1;
  Reference<double> r{};
  r.pos[0] = std::sin(w * t), r.pos[1] = std::sin(2 * w * t);
  r.vel[0] = w * std::cos(w * t), r.vel[1] = 2 * w * std::cos(2 * w * t);
  return r;
}

void expectRel(double got, double want, double rel, const char* what) {
  EXPECT_NEAR(got, want, rel * (1.0 + std::fabs(want))) << what;
}

}  // namespace

// The spec's first step (corrected model, default gains): the dynamic
// controller at t = 0, then one dynamic model step.
TEST(Pioneer3dx, FirstStepAsTheOriginal) {
  const Pioneer3dx::Params<double> p = aurora_sim::referencePioneerParams();
  Pioneer3dx::State<double> s = start(p);
  EXPECT_EQ(s.X[aurora_sim::kX], 0.15);
  PioneerDynamic::Memory<double> m;
  m.reset();
  double U[2], err[3];
  PioneerDynamic::command(p, aurora_control::PioneerDynamicGains<double>::defaults(), m, lemniscate(0.0), s.X, U, err);
  expectRel(U[0], 0.05843564625337886, 1e-13, "u_ref");
  EXPECT_EQ(U[1], 1.0);  // omega_ref saturates
  Pioneer3dx::step(p, s, U);
  expectRel(s.X[aurora_sim::kPioneerU], 0.010947104955672323, 1e-13, "u");
  expectRel(s.X[aurora_sim::kPioneerOmega], 0.46125461254612549, 1e-13, "omega");
  expectRel(s.X[aurora_sim::kX], 0.15109471049556722, 1e-13, "x");
  expectRel(s.X[aurora_sim::kY], 0.0069188191881918827, 1e-13, "y");
  expectRel(s.X[aurora_sim::kYaw], 0.046125461254612553, 1e-13, "yaw");
  // The published omega gain (theta2 instead of 1/theta2): omega = 0.02168.
  Pioneer3dx::Params<double> bug = p;
  bug.omega_gain_bug = 1.0;
  Pioneer3dx::State<double> b = start(bug);
  Pioneer3dx::step(bug, b, U);
  expectRel(b.X[aurora_sim::kPioneerOmega], 0.02168, 1e-13, "omega with the published gain");
}

// The kinematic law's reference velocity (Ur before saturation, spec:
// (0.058200445512964952, 1) after it) and its own limits.
TEST(Pioneer3dx, TheKinematicLawSaturatesAsTheOriginal) {
  const Pioneer3dx::Params<double> p = aurora_sim::referencePioneerParams();
  Pioneer3dx::State<double> s = start(p);
  PioneerKinematic::Memory<double> m;
  double U[2], err[3];
  PioneerKinematic::command(p, aurora_control::PioneerKinematicGains<double>::defaults(), m, lemniscate(0.0), s.X, U,
                            err);
  expectRel(U[0], 0.058200445512964952, 1e-13, "u_r");
  EXPECT_EQ(U[1], 1.0);
  EXPECT_EQ(err[2], 0.0);  // a ground robot's error is planar
}

// The kinematic model: the velocities are the commands; the pose moves by
// them at the heading before the step.
TEST(Pioneer3dx, TheKinematicModelTakesTheCommandAsItsVelocity) {
  Pioneer3dx::Params<double> p = aurora_sim::referencePioneerParams();
  p.kinematic = 1.0;
  Pioneer3dx::State<double> s = start(p);
  const double U[2] = {0.3, 0.5};
  Pioneer3dx::step(p, s, U);
  EXPECT_EQ(s.X[aurora_sim::kPioneerU], 0.3);
  EXPECT_EQ(s.X[aurora_sim::kPioneerOmega], 0.5);
  EXPECT_DOUBLE_EQ(s.X[aurora_sim::kX], 0.15 + 0.3 * 0.1);
  EXPECT_DOUBLE_EQ(s.X[aurora_sim::kY], 0.15 * 0.5 * 0.1);
  EXPECT_DOUBLE_EQ(s.X[aurora_sim::kYaw], 0.05);
}

// The spec's scenario: two laps of the lemniscate (k = 0 .. 1256, Ts 0.1 s),
// the dynamic controller on the dynamic model: below 5 cm after 20 s.
TEST(Pioneer3dx, TracksTheLemniscate) {
  const Pioneer3dx::Params<double> p = aurora_sim::referencePioneerParams();
  Pioneer3dx::State<double> s = start(p);
  PioneerDynamic::Memory<double> m;
  m.reset();
  const auto g = aurora_control::PioneerDynamicGains<double>::defaults();
  double worst = 0.0;
  for (long k = 0; k <= 1256; ++k) {
    const double t = double(k) * p.Ts;
    const Reference<double> r = lemniscate(t);
    if (t > 20.0) worst = std::max(worst, std::hypot(r.pos[0] - s.X[0], r.pos[1] - s.X[1]));
    double U[2], err[3];
    PioneerDynamic::command(p, g, m, r, s.X, U, err);
    Pioneer3dx::step(p, s, U);
  }
  EXPECT_LT(worst, 0.05);
}

// A real Pioneer located by motion capture at its centre: the state the
// laws read is its control point's (eq. P3: a ahead, moving with
// K(psi) [u; omega]) with u, omega; the sim's body is that centre again.
TEST(Pioneer3dx, TheStateFromItsCentresPoseIsTheControlPoints) {
  using Profile = aurora_sim::SimProfile<Pioneer3dx>;
  const Pioneer3dx::Params<double> p = aurora_sim::referencePioneerParams();
  const double psi = 2.5, u = 0.3, omega = -0.4, c[2] = {1.2, -0.7};
  double body[aurora_sim::kStateSize] = {};
  body[aurora_sim::kX] = c[0], body[aurora_sim::kY] = c[1], body[aurora_sim::kYaw] = psi;
  body[aurora_sim::kVx] = u * std::cos(psi), body[aurora_sim::kVy] = u * std::sin(psi);
  body[aurora_sim::kYawRate] = omega;
  body[aurora_sim::kZ] = 0.21, body[aurora_sim::kRoll] = 0.01;  // the markers' height and a tilt: not the state's
  double X[Pioneer3dx::kStates], v[3];
  Profile::stateFromBody(p, body, X);
  aurora_sim::pioneerPointVelocity(p.a, psi, u, omega, v);
  EXPECT_NEAR(X[aurora_sim::kX], c[0] + p.a * std::cos(psi), 1e-15);
  EXPECT_NEAR(X[aurora_sim::kY], c[1] + p.a * std::sin(psi), 1e-15);
  EXPECT_EQ(X[aurora_sim::kZ], 0.0);
  EXPECT_EQ(X[aurora_sim::kRoll], 0.0);
  EXPECT_NEAR(X[aurora_sim::kVx], v[0], 1e-15);
  EXPECT_NEAR(X[aurora_sim::kVy], v[1], 1e-15);
  EXPECT_EQ(X[aurora_sim::kYawRate], omega);
  EXPECT_NEAR(X[aurora_sim::kPioneerU], u, 1e-15);
  EXPECT_EQ(X[aurora_sim::kPioneerOmega], omega);
  double back[3];
  Profile::bodyPosition(p, X, back);
  EXPECT_NEAR(back[0], c[0], 1e-15);
  EXPECT_NEAR(back[1], c[1], 1e-15);
}

TEST(Pioneer3dx, TheSafetyLayersSpeedLimitsBoundWhatIsSent) {
  double U[2] = {0.8, -1.5};
  aurora_sim::SimProfile<Pioneer3dx>::limitSpeed(U, 0.5, 1.0);
  EXPECT_EQ(U[0], 0.5);
  EXPECT_EQ(U[1], -1.0);
  double V[2] = {0.8, -1.5};
  aurora_sim::SimProfile<Pioneer3dx>::limitSpeed(V, 0.0, 0.0);  // 0: no limit
  EXPECT_EQ(V[0], 0.8);
  EXPECT_EQ(V[1], -1.5);
}

TEST(Pioneer3dx, TheVehicleFileIsTheReference) {
  const std::string path = std::string(AURORA_CONFIG_DIR) + "/vehicles/pioneer3dx.yaml";
  const Pioneer3dx::Params<double> file = aurora_sim::loadVehicleFile<Pioneer3dx>(path);
  const Pioneer3dx::Params<double> ref = aurora_sim::referencePioneerParams();
  EXPECT_EQ(file.Ts, ref.Ts);
  EXPECT_EQ(file.a, ref.a);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(file.theta[i], ref.theta[i]) << i;
  EXPECT_EQ(file.kinematic, 0.0);
  EXPECT_EQ(file.omega_gain_bug, 0.0);
  const std::string refusal = aurora_tests::configRefusal(
      [&] { aurora_sim::loadVehicleFile<aurora_sim::Bebop2>(path, "the controller 'bebop2_compensator'"); });
  EXPECT_NE(refusal.find("is of type 'pioneer3dx', but the controller 'bebop2_compensator' flies type 'bebop2'"),
            std::string::npos)
      << "a Bebop loop loaded a Pioneer file: '" << refusal << "'";
}

// The shipped controller files are AuRoRA's default gains; the standard
// scenario flown from its files (as flight and aurora.simulate load it)
// starts with the control point a ahead and gives the spec's first step.
TEST(Pioneer3dx, TheShippedFilesFlyTheStandardScenario) {
  const std::string c = AURORA_CONFIG_DIR;
  const auto kin = aurora_control::readLawFile<PioneerKinematic>(c + "/controllers/pioneer_kinematic.yaml", kPioneerTs).gains;
  const auto kin_default = PioneerKinematic::Gains<double>::defaults();
  const auto dyn = aurora_control::readLawFile<PioneerDynamic>(c + "/controllers/pioneer_dynamic.yaml", kPioneerTs).gains;
  const auto dyn_default = PioneerDynamic::Gains<double>::defaults();
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(kin.k1[i], kin_default.k1[i]);
    EXPECT_EQ(kin.k2[i], kin_default.k2[i]);
    EXPECT_EQ(dyn.kc1[i], dyn_default.kc1[i]);
    EXPECT_EQ(dyn.kc2[i], dyn_default.kc2[i]);
    EXPECT_EQ(dyn.kd1[i], dyn_default.kd1[i]);
    EXPECT_EQ(dyn.kd2[i], dyn_default.kd2[i]);
  }
  const aurora_control::FlightFiles files{c + "/controllers/pioneer_dynamic.yaml",
                                          c + "/tasks/pioneer_lemniscate.yaml", c + "/vehicles/pioneer3dx.yaml", ""};
  const auto f = aurora_control::loadLawFlight<PioneerDynamic>(files);
  EXPECT_EQ(f.steps, 1258);  // k = 0..1257
  std::vector<double> x, u;
  aurora_control::flyLaw<PioneerDynamic>(f.run, f.cfg, 2, [&](const auto& o, double) {
    x.push_back(o.X_before[aurora_sim::kX]);
    u.push_back(o.step.U[aurora_sim::kPioneerURef]);
  });
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[0], 0.15);
  expectRel(u[0], 0.05843564625337886, 1e-13, "u_ref at step 0");
  expectRel(x[1], 0.15109471049556722, 1e-13, "x after one step");
}

// The flight any law gets from its controller file without options of its
// own (loadLawFlight) reads its gains by its own reader; a law that
// saturates its own commands (the Pioneer's: lawSaturation) has no clamp and
// refuses to leave one out, another law (the compensator's) clamps as the
// drivers do unless asked not to.
TEST(Pioneer3dx, AnyLawsFlightReadsItsGainsByItsOwnReader) {
  const std::string c = AURORA_CONFIG_DIR;
  const aurora_control::FlightFiles files{c + "/controllers/pioneer_dynamic.yaml",
                                          c + "/tasks/pioneer_lemniscate.yaml", c + "/vehicles/pioneer3dx.yaml", ""};
  const auto any = aurora_control::loadLawFlight<PioneerDynamic>(files);
  const auto file = aurora_control::readLawFile<PioneerDynamic>(files.controller, kPioneerTs).gains;
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(any.run.gains.kc1[i], file.kc1[i]);
    EXPECT_EQ(any.run.gains.kd2[i], file.kd2[i]);
  }
  EXPECT_FALSE(any.cfg.clamp_commands);
  EXPECT_NE(aurora_control::lawSaturation<PioneerDynamic>(), nullptr);
  EXPECT_EQ(aurora_control::lawSaturation<aurora_control::Bebop2Compensator>(), nullptr);
  aurora_control::FlightFiles unclamped = files;
  unclamped.no_clamp = true;
  aurora_control::FlightOptionNames python;
  python.no_clamp_option = "clamp=False";
  const std::string unclamped_refusal =
      aurora_tests::configRefusal([&] { aurora_control::loadLawFlight<PioneerDynamic>(unclamped, python); });
  EXPECT_NE(unclamped_refusal.find("clamp=False is refused for the Pioneer P3-DX: its laws saturate"), std::string::npos)
      << "a Pioneer flight left out a clamp it does not have: '" << unclamped_refusal << "'";
  // The compensator's file without its own reader's key (clamp_commands).
  const std::string compensator = ::testing::TempDir() + "compensator_gains_only.yaml";
  {
    std::ifstream in(c + "/controllers/bebop2_compensator.yaml");
    std::ofstream out(compensator);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("clamp_commands", 0) != 0) out << line << "\n";
    }
  }
  const aurora_control::FlightFiles bebop{compensator, c + "/tasks/bebop2_waypoints.yaml", c + "/vehicles/bebop2.yaml", ""};
  EXPECT_TRUE(aurora_control::loadLawFlight<aurora_control::Bebop2Compensator>(bebop).cfg.clamp_commands);
  aurora_control::FlightFiles bebop_unclamped = bebop;
  bebop_unclamped.no_clamp = true;
  EXPECT_FALSE(aurora_control::loadLawFlight<aurora_control::Bebop2Compensator>(bebop_unclamped).cfg.clamp_at_drone);
  aurora_control::FlightFiles wrong = files;
  wrong.controller = c + "/controllers/pioneer_kinematic.yaml";  // k1, k2: not the dynamic law's keys
  const std::string wrong_refusal = aurora_tests::configRefusal([&] { aurora_control::loadLawFlight<PioneerDynamic>(wrong); });
  EXPECT_NE(wrong_refusal.find("controller.k1"), std::string::npos)
      << "a kinematic law's file read as the dynamic law's: '" << wrong_refusal << "'";
}

namespace {

// The ConfigError a Pioneer dynamic controller file of `text` is refused with.
std::string refusalOf(const std::string& text) {
  const std::string path = testing::TempDir() + "/pioneer_controller.yaml";
  std::ofstream(path) << text;
  return aurora_tests::configRefusal([&] { aurora_control::readLawFile<PioneerDynamic>(path, kPioneerTs); });
}

}  // namespace

TEST(Pioneer3dx, ABadControllerFileIsRefusedNamingTheKey) {
  const std::string good = "controller: {name: pioneer_dynamic, kc1: [0.35, 0.35], kc2: [0.8, 0.8], "
                           "kd1: [0.75, 0.75], kd2: [0.12, 0.035]}";
  EXPECT_EQ(refusalOf(good), "");
  std::string e = refusalOf("controller: {name: pioneer_dynamic, kc1: [0.35, 0.35], kc2: [0.8, 0.8], "
                            "kd1: [0.75, 0.75], kd2: [0.12, -1]}");
  EXPECT_NE(e.find("'controller.kd2' must be a list of 2 numbers in [0, 10] (u, omega)"), std::string::npos) << e;
  e = refusalOf("controller: {name: pioneer_dynamic, kc1: [0.35], kc2: [0.8, 0.8], kd1: [0.75, 0.75], "
                "kd2: [0.12, 0.035]}");
  EXPECT_NE(e.find("controller.kc1"), std::string::npos) << e;
  e = refusalOf("controller: {name: pioneer_dynamic, k1: [0.35, 0.35], kc2: [0.8, 0.8], kd1: [0.75, 0.75], "
                "kd2: [0.12, 0.035]}");
  EXPECT_NE(e.find("'controller.k1' is not a known key: accepted name, kc1, kc2, kd1, kd2, accel_interval"),
            std::string::npos) << e;
  // The acceleration's interval (AuRoRA's 2018 law: 0.1 s at any period): optional, [0, 10] s.
  EXPECT_EQ(refusalOf(good.substr(0, good.size() - 1) + ", accel_interval: 0.1}"), "");
  e = refusalOf(good.substr(0, good.size() - 1) + ", accel_interval: -1}");
  EXPECT_NE(e.find("'controller.accel_interval' = -1 is outside the accepted range [0, 10]"), std::string::npos) << e;
}

// A rate given for a law is accepted only for the laws that declare one of
// their own (lawHasRate): the Pioneer's laws and the AR.Drone's run every
// model step, and the refusal names the laws that have a rate.
TEST(Pioneer3dx, ARateIsRefusedForALawThatHasNoneOfItsOwn) {
  EXPECT_TRUE(aurora_control::lawHasRate<aurora_control::Bebop2Compensator>());
  EXPECT_FALSE(aurora_control::lawHasRate<PioneerDynamic>());
  EXPECT_EQ(aurora_common::entryNames([](auto&& f) { aurora_control::forEachLawWithARate(f); }), "bebop2_compensator");
  EXPECT_NO_THROW(aurora_control::refuseRateFor("bebop2_compensator", 10.0, "--rate"));
  EXPECT_NO_THROW(aurora_control::refuseRateFor("pioneer_dynamic", 0.0, "--rate"));  // none given
  const std::string refusal = aurora_tests::configRefusal([] { aurora_control::refuseRateFor("pioneer_kinematic", 5.0, "--rate"); });
  EXPECT_NE(refusal.find("--rate is refused here: it sets the rate of a law that runs at one of its own "
                         "(bebop2_compensator); 'pioneer_kinematic'"),
            std::string::npos)
      << "a rate for the Pioneer's kinematic law: '" << refusal << "'";
}
