// Unit tests of the ROS-free model core: angle wrapping, command clamping and
// mapping, hover equilibrium, and the shipped vehicle file against the spec.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <fstream>
#include <iterator>
#include <sstream>

#include "aurora_sim/vehicle/ardrone2/ardrone_model.h"
#include "aurora_sim/command_mapping.h"
#include "aurora_sim/vehicle/ardrone2/ardrone_keys.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

using namespace aurora_sim;
using namespace aurora_common;

namespace {
using aurora_common::kPi;
}

TEST(AngleWrap, WrapsOnceIntoPiRange) {
  EXPECT_DOUBLE_EQ(wrapAngleOnce(0.5), 0.5);
  EXPECT_DOUBLE_EQ(wrapAngleOnce(kPi), kPi);  // pi itself is kept
  EXPECT_NEAR(wrapAngleOnce(kPi + 0.25), -kPi + 0.25, 1e-15);
  EXPECT_NEAR(wrapAngleOnce(-kPi - 0.25), kPi - 0.25, 1e-15);
  EXPECT_NEAR(wrapAngleOnce(3.0 * kPi / 2.0), -kPi / 2.0, 1e-15);
}

TEST(AngleWrap, ModelStepWrapsYaw) {
  ArdroneParams<double> p = referenceArdrone2Params();
  ArdroneState<double> s;
  s.reset();
  s.X[kYaw] = kPi - 1e-3;
  s.X[kYawRate] = 1.0;  // crosses +pi within one step (1/30 rad)
  const double U[4] = {0, 0, 0, 0};
  ardroneStep(p, s, U, Disturbance<double>::zero());
  EXPECT_LT(s.X[kYaw], -kPi + 0.1);
  EXPECT_GE(s.X[kYaw], -kPi);
}

TEST(CommandClamp, ClampsToUnitInterval) {
  EXPECT_EQ(clampUnit(1.7), 1.0);
  EXPECT_EQ(clampUnit(-3.0), -1.0);
  EXPECT_EQ(clampUnit(0.25), 0.25);
  EXPECT_EQ(clampUnit(1.0), 1.0);
  EXPECT_EQ(clampUnit(-1.0), -1.0);
}

TEST(CommandMapping, DriverConventionRoundTripsExactly) {
  // linear = a for the delay-study law U = [-a_y, -a_x, a_z, 0].
  const TwistCommand t{0.1, -0.2, 0.3, 0.4};
  double U[4];
  modelCommandFromTwist(t, U);
  EXPECT_EQ(U[kURoll], 0.2);
  EXPECT_EQ(U[kUPitch], -0.1);
  EXPECT_EQ(U[kUClimb], 0.3);
  EXPECT_EQ(U[kUYawRate], -0.4);
  const TwistCommand back = twistFromModelCommand(U);
  EXPECT_EQ(back.linear_x, t.linear_x);
  EXPECT_EQ(back.linear_y, t.linear_y);
  EXPECT_EQ(back.linear_z, t.linear_z);
  EXPECT_EQ(back.angular_z, t.angular_z);
}

TEST(CommandMapping, DetectsNonFinite) {
  const double ok[4] = {0, 1, -1, 0.5};
  const double bad[4] = {0, std::numeric_limits<double>::quiet_NaN(), 0, 0};
  const double inf[4] = {0, 0, std::numeric_limits<double>::infinity(), 0};
  EXPECT_TRUE(allFinite(ok, 4));
  EXPECT_FALSE(allFinite(bad, 4));
  EXPECT_FALSE(allFinite(inf, 4));
}

TEST(ArdroneModel, HoversNearStartWithZeroCommand) {
  // Zero command: the on-board loops hold attitude and zero climb rate; the
  // drone must not drift away or fall out of the sky in 10 s.
  ArdroneParams<double> p = referenceArdrone2Params();
  ArdroneState<double> s;
  s.reset();
  const double U[4] = {0, 0, 0, 0};
  for (int k = 0; k < 300; ++k) ardroneStep(p, s, U, Disturbance<double>::zero());
  EXPECT_NEAR(s.X[kX], 0.0, 1e-9);
  EXPECT_NEAR(s.X[kY], 0.0, 1e-9);
  EXPECT_NEAR(s.X[kZ], 0.75, 0.2);
  EXPECT_NEAR(s.X[kVz], 0.0, 0.01);
}

TEST(ArdroneModel, PositiveCommandsTiltAsTheSpecSays) {
  // A positive u_theta commands a negative pitch; positive u_phi a positive roll.
  ArdroneParams<double> p = referenceArdrone2Params();
  ArdroneState<double> s;
  s.reset();
  const double U[4] = {0.5, 0.5, 0, 0};
  for (int k = 0; k < 30; ++k) ardroneStep(p, s, U, Disturbance<double>::zero());
  EXPECT_GT(s.X[kRoll], 0.0);
  EXPECT_LT(s.X[kPitch], 0.0);
}

TEST(ArdroneModel, FloatInstantiationTracksDouble) {
  ArdroneParams<double> pd = referenceArdrone2Params();
  ArdroneParams<float> pf = pd.cast<float>();
  ArdroneState<double> sd;
  ArdroneState<float> sf;
  sd.reset();
  sf.reset();
  const double Ud[4] = {0.1, -0.2, 0.3, 0.05};
  const float Uf[4] = {0.1f, -0.2f, 0.3f, 0.05f};
  for (int k = 0; k < 60; ++k) {
    ardroneStep(pd, sd, Ud, Disturbance<double>::zero());
    ardroneStep(pf, sf, Uf, Disturbance<float>::zero());
  }
  for (int i = 0; i < kStateSize; ++i) EXPECT_NEAR(sf.X[i], sd.X[i], 1e-3) << "state " << i;
}

TEST(VehicleFile, ShippedArdrone2MatchesSpecExactly) {
  const ArdroneParams<double> p =
      aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(std::string(AURORA_CONFIG_DIR) + "/vehicles/ardrone2.yaml");
  const ArdroneParams<double> ref = referenceArdrone2Params();
  // Bitwise equal: the ROS loop reads the file, the runner may use either.
  EXPECT_EQ(p.Ts, ref.Ts);
  EXPECT_EQ(p.g, ref.g);
  EXPECT_EQ(p.m, ref.m);
  EXPECT_EQ(p.Cf, ref.Cf);
  EXPECT_EQ(p.Ct, ref.Ct);
  EXPECT_EQ(p.Jm, ref.Jm);
  EXPECT_EQ(p.Km, ref.Km);
  EXPECT_EQ(p.Vo, ref.Vo);
  EXPECT_EQ(p.Wo, ref.Wo);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(p.uSat[i], ref.uSat[i]) << "uSat " << i;
}

TEST(VehicleFile, RangeCheckNamesKeyAndRange) {
  const VehicleKey& mass = vehicleKeys()[2];
  const std::string msg = checkVehicleValue("/ardrone1/vehicle/", mass, -1.0);
  EXPECT_NE(msg.find("/ardrone1/vehicle/mass"), std::string::npos) << msg;
  EXPECT_NE(msg.find("accepted range"), std::string::npos) << msg;
  EXPECT_NE(checkVehicleValue("v/", mass, std::nan("")), "");
}

TEST(VehicleFile, MissingKeyIsNamed) {
  const std::string path = ::testing::TempDir() + "/vehicle_no_mass.yaml";
  {
    std::ofstream f(path);
    f << "type: ardrone2\nsample_time: 0.03333333333333333\ngravity: 9.8\n";
  }
  try {
    aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(path);
    FAIL() << "accepted a file without mass";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'mass'"), std::string::npos) << e.what();
  }
}

// The shipped file with its `type:` line replaced by `type_line`: the
// refusal of loading it for `flown_by`.
std::string typeRefusal(const std::string& type_line, const std::string& flown_by = "this loop") {
  std::ifstream in(std::string(AURORA_CONFIG_DIR) + "/vehicles/ardrone2.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find("type: ardrone2");
  text.replace(at, text.find('\n', at) - at, type_line);
  const std::string path = ::testing::TempDir() + "/vehicle_type.yaml";
  std::ofstream(path) << text;
  try {
    aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(path, flown_by);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// A file says which vehicle it describes: missing, unknown and (for a loop
// of another vehicle) foreign types are refused naming the file, the type
// and what is accepted; the shipped file's type loads.
TEST(VehicleFile, ItsTypeNamesTheVehicle) {
  EXPECT_EQ(typeRefusal("type: ardrone2"), "");
  const std::string missing = typeRefusal("", "the controller 'pd_saturated'");
  EXPECT_NE(missing.find("vehicle_type.yaml': lacks the key 'type'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("add 'type: ardrone2'"), std::string::npos) << missing;
  const std::string unknown = typeRefusal("type: ardrone3");
  EXPECT_NE(unknown.find("type 'ardrone3' is not a vehicle this build knows (accepted: ardrone2, bebop2, pioneer3dx)"), std::string::npos)
      << unknown;
  // A loop of another vehicle (a test-only one) refuses an AR.Drone's file, naming both.
  struct Rover {
    static const char* name() { return "rover"; }
  };
  const std::string foreign = vehicleTypeRefusal<Rover>("ardrone2", "the controller 'rover_law'");
  EXPECT_EQ(foreign, "is of type 'ardrone2', but the controller 'rover_law' flies type 'rover': give a vehicle file "
                     "of type 'rover' (config/vehicles/rover.yaml), or a controller for 'ardrone2'");
}
