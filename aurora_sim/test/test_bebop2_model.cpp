// The Bebop 2's model (docs/bebop2.md, eq. B1) against the values the
// spec computed with AuRoRA's own code, its vehicle file, and the vehicle
// file's type rule.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "aurora_sim/vehicle/bebop2/bebop2.h"
#include "aurora_sim/vehicle/pioneer3dx/pioneer3dx.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace {

using aurora_sim::Bebop2;

// The spec's start: (x, y, z, yaw) = (1, -2, 1, 3.1), their rates
// (0.4, -0.3, 0.1, 0.2); roll and pitch 0.
Bebop2::State<double> specState() {
  Bebop2::State<double> s;
  s.reset();
  const double pos[4] = {1.0, -2.0, 1.0, 3.1}, vel[4] = {0.4, -0.3, 0.1, 0.2};
  const int at[4] = {aurora_sim::kX, aurora_sim::kY, aurora_sim::kZ, aurora_sim::kYaw};
  for (int i = 0; i < 4; ++i) s.X[at[i]] = pos[i], s.X[at[i] + 6] = vel[i];
  return s;
}

// x y z yaw, then their rates, after one step with U = (0.3, -0.2, 0.1, 0.5).
void expectStep(bool rotated_drag, const double want[8]) {
  Bebop2::Params<double> p = aurora_sim::referenceBebop2Params();
  p.rotated_drag = rotated_drag ? 1.0 : 0.0;
  Bebop2::State<double> s = specState();
  const double U[4] = {0.3, -0.2, 0.1, 0.5};
  Bebop2::step(p, s, U);
  const int at[8] = {aurora_sim::kX,  aurora_sim::kY,  aurora_sim::kZ,  aurora_sim::kYaw,
                     aurora_sim::kVx, aurora_sim::kVy, aurora_sim::kVz, aurora_sim::kYawRate};
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(s.X[at[i]], want[i], 1e-15 * (1.0 + std::fabs(want[i]))) << i;
  for (int i : {aurora_sim::kRoll, aurora_sim::kPitch, aurora_sim::kRollRate, aurora_sim::kPitchRate}) {
    EXPECT_EQ(s.X[i], 0.0) << i;
  }
}

}  // namespace

TEST(Bebop2Model, OneStepAsTheOriginal) {
  const double corrected[8] = {1.0129797196447599,  -2.0097458666289127,  1.0033294444444445,  3.1110892222222222,
                               0.38939158934279494, -0.29237599886737697, 0.099883333333333338, 0.33267666666666668};
  expectStep(false, corrected);
  // The published model's drag turned by the yaw: x, y and their rates differ.
  const double rotated[8] = {1.0131392979572746,  -2.009863152416822,   1.0033294444444445,  3.1110892222222222,
                             0.39417893871823606, -0.29589457250465873, 0.099883333333333338, 0.33267666666666668};
  expectStep(true, rotated);
}

TEST(Bebop2Model, TheYawWrapsOnceIntoPlusMinusPi) {
  Bebop2::Params<double> p = aurora_sim::referenceBebop2Params();
  Bebop2::State<double> s;
  s.reset();
  s.X[aurora_sim::kYaw] = 3.1;
  s.X[aurora_sim::kYawRate] = 3.0;  // 0.1 rad in one step: past pi
  const double U[4] = {0, 0, 0, 0};
  Bebop2::step(p, s, U);
  EXPECT_LT(s.X[aurora_sim::kYaw], 0.0);
  EXPECT_NEAR(s.X[aurora_sim::kYaw], 3.1 + s.X[aurora_sim::kYawRate] * p.Ts - 2.0 * aurora_common::kPi, 1e-15);
}

TEST(Bebop2Model, TheVehicleFileIsTheReference) {
  const std::string path = std::string(AURORA_CONFIG_DIR) + "/vehicles/bebop2.yaml";
  const Bebop2::Params<double> file = aurora_sim::loadVehicleFile<Bebop2>(path);
  const Bebop2::Params<double> ref = aurora_sim::referenceBebop2Params();
  EXPECT_EQ(file.Ts, ref.Ts);
  for (int i = 0; i < aurora_sim::kBebopAxes; ++i) {
    EXPECT_EQ(file.Ku[i], ref.Ku[i]) << i;
    EXPECT_EQ(file.Kv[i], ref.Kv[i]) << i;
  }
  EXPECT_EQ(file.rotated_drag, 0.0);
  // An AR.Drone loop refuses the Bebop's file, naming both.
  try {
    aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(path, "the controller 'pd_saturated'");
    ADD_FAILURE() << "an AR.Drone loop loaded a Bebop 2 file";
  } catch (const aurora_common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("is of type 'bebop2', but the controller 'pd_saturated' flies type "
                                         "'ardrone2'"),
              std::string::npos)
        << e.what();
  }
}

// The drag option is a flag: a number there is refused naming the key.
TEST(Bebop2Model, TheDragOptionIsTrueOrFalse) {
  const std::string path = ::testing::TempDir() + "bebop2_bad_flag.yaml";
  {
    std::ifstream in(std::string(AURORA_CONFIG_DIR) + "/vehicles/bebop2.yaml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string key = "model_bug_rotated_drag: false";
    text.replace(text.find(key), key.size(), "model_bug_rotated_drag: 0.5");
    std::ofstream(path) << text;
  }
  try {
    aurora_sim::loadVehicleFile<Bebop2>(path);
    ADD_FAILURE() << "0.5 was taken for a flag";
  } catch (const aurora_common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("'model_bug_rotated_drag' is not true or false"), std::string::npos)
        << e.what();
  }
}

// Its driver's cmd_vel carries the model's commands as they are.
TEST(Bebop2Model, CmdVelIsTheCommandAsItIs) {
  const double U[4] = {0.1, -0.2, 0.3, -0.4};
  const aurora_sim::TwistCommand t = Bebop2::toDriver(U);
  EXPECT_EQ(t.linear_x, 0.1);
  EXPECT_EQ(t.linear_y, -0.2);
  EXPECT_EQ(t.linear_z, 0.3);
  EXPECT_EQ(t.angular_z, -0.4);
  double back[4];
  Bebop2::fromDriver(t, back);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(back[i], U[i]);
}

namespace {

// The shipped file of `vehicle` with `from` replaced by `to`: the refusal
// of loading it as a Vehicle ("" when it loads).
template <class Vehicle>
std::string refusalOfEdited(const std::string& from, const std::string& to) {
  std::ifstream in(std::string(AURORA_CONFIG_DIR) + "/vehicles/" + Vehicle::name() + ".yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find(from);
  if (at == std::string::npos) return "the test's edit '" + from + "' is not in the file";
  text.replace(at, from.size(), to);
  const std::string path = ::testing::TempDir() + "/edited_" + Vehicle::name() + ".yaml";
  std::ofstream(path) << text;
  try {
    aurora_sim::loadVehicleFile<Vehicle>(path);
  } catch (const aurora_common::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The other vehicles' files are read as strictly as the AR.Drone's: a
// missing, unknown or out-of-range key is refused naming it and what is
// accepted (issue 33: a Ku of zero, a negative theta1).
TEST(VehicleFile, TheOtherVehiclesFilesAreCheckedKeyByKey) {
  using aurora_sim::Pioneer3dx;
  EXPECT_EQ(refusalOfEdited<Bebop2>("z: 3.966", "z: 3.966"), "");
  std::string e = refusalOfEdited<Bebop2>("z: 3.966", "z: 0.0");
  EXPECT_NE(e.find("input_gain/z"), std::string::npos) << e;
  EXPECT_NE(e.find("accepted range"), std::string::npos) << e;
  e = refusalOfEdited<Bebop2>("  z: 3.966", "  zz: 3.966");
  EXPECT_NE(e.find("lacks the key 'input_gain/z'"), std::string::npos) << e;
  e = refusalOfEdited<Bebop2>("model_bug_rotated_drag: false", "model_bug_rotated_drag: false\nmass: 0.5");
  EXPECT_NE(e.find("'mass' is not a key of a bebop2 file: accepted type, sample_time, input_gain/x"),
            std::string::npos) << e;
  e = refusalOfEdited<Pioneer3dx>("theta1: 0.5338", "theta1: -0.5338");
  EXPECT_NE(e.find("dynamics/theta1"), std::string::npos) << e;
  EXPECT_NE(e.find("accepted range"), std::string::npos) << e;
  e = refusalOfEdited<Pioneer3dx>("control_point: 0.15", "control_point: 0.15\nwheel_base: 0.4");
  EXPECT_NE(e.find("'wheel_base' is not a key of a pioneer3dx file"), std::string::npos) << e;
  e = refusalOfEdited<Pioneer3dx>("kinematic_model: false", "kinematic_model: maybe");
  EXPECT_NE(e.find("'kinematic_model' is not true or false"), std::string::npos) << e;
}
