// The shape seam (issue 32): a shape of three robots defined only under
// test/ (three_abreast.h) flies through the generic formation code of
// every backend, with no edit outside test/: the offline runner
// (runFormation), the sweep's scalar loop (simulateFormation), its SIMD
// engine (FormationBatch on this build's default instruction set) and the
// CUDA kernel's per-thread entry (formationThread, on the host for every
// thread of a launch). Its sweep parameters sit where its ShapeLayout puts
// them: three delays, 18 gains, three robots' own link values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#ifdef AURORA_SWEEP_LANES  // xsimd >= 8 (Ubuntu 20.04's xsimd 7: no SIMD engine to test)
#include "../src/lanes/batch_engine.h"
#else
#include "aurora_sweep/backends.h"
#endif
#include "aurora_control/formation/triangle/triangle_formation.h"
#include "aurora_control/formation/triangle/triangle_reference.h"
#include "aurora_control/law/either_law.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "aurora_sweep/kernel_entry.h"
#include "sweep_test_support.h"
#include "point_mass.h"
#include "three_abreast.h"

namespace {

using namespace aurora_sweep;
using test::differing;
using aurora_control::LawType;
using three_abreast::ThreeAbreast;
template <typename T, class Data = aurora_control::ArdroneLawData>
using Run3 = ShapeRun<T, ThreeAbreast, Data>;
template <typename T, class Law>
using Setup3 = FormationSetup<T, ThreeAbreast, typename Law::Data>;
using DroneLaw = aurora_control::ArdroneLaw<LawType::kUnderactuated>;
using PointLaw = point_mass::PointPd;
using MixedLaw = aurora_control::EitherLaw<DroneLaw, PointLaw>;  // an AR.Drone or a point mass, per robot
constexpr ShapeLayout kAt = shapeLayout<ThreeAbreast<double>>();
constexpr int kCapacity = 64;

// Three robots of `vehicle` flying `gains` at 1 m, told to hold robot 1
// at (0.5, 0.5, 1.5) with robot 2 1.5 m along x and robot 3 1.5 m along y.
template <class Data>
Run3<double, Data> threeRobots(const typename Data::Vehicle::template Params<double>& vehicle,
                               const typename Data::template Gains<double>& gains,
                               const aurora_control::LinkParams& link) {
  Run3<double, Data> run;
  const double starts[3][3] = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  for (int d = 0; d < 3; ++d) {
    auto& robot = run.drone[d];
    robot.plant = robot.model = vehicle;
    robot.gains = gains;
    robot.link = link;
    for (int i = 0; i < 3; ++i) robot.start[i] = starts[d][i];
  }
  for (int i = 0; i < 9; ++i) run.gains.k1[i] = i < 2 ? 0.1 : 0.5, run.gains.k2[i] = 0.5;
  const double Q[9] = {0.5, 0.5, 1.5, 1.5, 0, 0, 0, 1.5, 0};
  for (int i = 0; i < 9; ++i) run.reference.Q[i] = Q[i];
  run.schedule.period_ticks = 6;
  return run;
}

// The AR.Drone (the vehicle file's) with the lab's formation gains.
aurora_sim::Ardrone2::Params<double> ardrone() {
  return aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(test::configDir() + "/vehicles/ardrone2.yaml");
}
aurora_control::LawGains<double> droneGains() {
  aurora_control::LawGains<double> gains;
  gains.pd = {0.5, 0.85};
  gains.underactuated = aurora_control::UnderactuatedGains<double>::defaults();
  gains.underactuated.k1[0] = gains.underactuated.k1[1] = 0.1;
  gains.underactuated.k2[4] = 15.0;
  return gains;
}

// The point mass (the test vehicle) of 0.5 kg and its gains.
const point_mass::Params<double> kPoint{1.0 / 30.0, 0.5};
const point_mass::Gains<double> kPointGains{2.0, 3.0};

Run3<double> threeDrones(const aurora_control::LinkParams& link) {
  return threeRobots<aurora_control::ArdroneLawData>(ardrone(), droneGains(), link);
}

Run3<double, PointLaw> threePoints(const aurora_control::LinkParams& link) {
  return threeRobots<PointLaw>(kPoint, kPointGains, link);
}

// A mixed crew: robot d a point mass where `points[d]`, else an AR.Drone,
// each with its own law (MixedLaw: the robots' type).
Run3<double, MixedLaw> mixedCrew(const bool points[3], const aurora_control::LinkParams& link) {
  using Params = MixedLaw::Vehicle::Params<double>;
  MixedLaw::Gains<double> gains;
  gains.first = droneGains();
  gains.second = kPointGains;
  Run3<double, MixedLaw> run = threeRobots<MixedLaw>(Params::ofFirst(ardrone()), gains, link);
  for (int d = 0; d < 3; ++d) {
    if (points[d]) run.drone[d].plant = run.drone[d].model = Params::ofSecond(kPoint);
  }
  return run;
}

template <typename T, class Data>
FormationSetup<T, ThreeAbreast, Data> setupOf(const Run3<double, Data>& run) {
  FormationSetup<T, ThreeAbreast, Data> s;
  s.run = castFormationRun<T>(run);
  s.criteria = aurora_control::FormationCriteria<double>::study().cast<T>();
  s.iterations = aurora_control::formationTicks(40.0, run.drone[0].plant.Ts);
  s.early_stop = false;
  s.ideal_link = true;
  for (int d = 0; d < 3; ++d) s.ideal_link = s.ideal_link && run.drone[d].link.ideal();
  return s;
}

// delay_1 x delay_2 x delay_3 x formation_k1 of robot 2's x offset (24
// combinations); robot 3's own uplink loss `loss_3` (NaN: its file's).
// Delays up to 8 samples: beyond, robots brush past each other and the
// last bits of xsimd's sin against libm's grow into other distances.
struct ThreeGrid {
  std::vector<std::vector<double>> axes{{0, 3}, {0, 6}, {0, 4, 8}, {0.5, 1.0}};
  GridView view{};
  explicit ThreeGrid(double loss_3) {
    const int params[4] = {kAt.delay(0), kAt.delay(1), kAt.delay(2), kAt.k1(3)};
    for (int i = 0; i < kParamCount; ++i) view.fixed[i] = std::nan("");
    for (int i = 0; i < kAt.variables; ++i) view.fixed[kAt.k1(i)] = 0.5, view.fixed[kAt.k2(i)] = 0.5;
    view.fixed[kAt.linkValue(2, aurora_control::kLinkUplinkLoss)] = loss_3;
    test::setAxes(view, params, axes);
  }
};

template <class Law, typename T, bool Linked>
std::vector<SimResult> scalarLoop(const Setup3<T, Law>& setup, const GridView& grid) {
  std::vector<SimResult> out;
  for (long i = 0; i < grid.size(); ++i) out.push_back(simulateFormation<Law, T, kCapacity, Linked>(setup, grid, i));
  return out;
}

template <class Law, typename T, bool Linked>
std::vector<SimResult> kernelThreads(const Setup3<T, Law>& setup, const GridView& grid) {
  return test::launchOnHost(grid.size(), 8, [&](unsigned b, unsigned block, unsigned t, SimResult* out) {
    formationThread<Law, T, kCapacity, Linked>(setup, grid, 0, grid.size(), out, b, block, t);
  });
}

#ifdef AURORA_SWEEP_LANES
template <class Law, typename T>
std::vector<SimResult> simdLanes(const Setup3<T, Law>& setup, const GridView& grid) {
  std::vector<SimResult> out(static_cast<size_t>(grid.size()));
  std::atomic<long> next{0};
  Progress progress{0};
  LaneWork work(grid, 0, grid.size(), out, next, progress);
  FormationBatch<T, xsimd::default_arch, Law, ThreeAbreast>(setup, kCapacity, work).run();
  EXPECT_EQ(progress.load(), grid.size());
  return out;
}
#endif

// The offline runner (the flight tool's) on combination i's run, judged as
// a sweep judges it; its drones' positions at the end into `end`.
template <class Law, typename T>
SimResult runner(const Setup3<T, Law>& setup, const GridView& grid, long i, T end[9] = nullptr) {
  using Data = typename Law::Data;
  const Run3<T, Data> run = formationCombination<Law>(setup, grid.decode(i));
  using Judge = aurora_control::FormationJudge<T, ThreeAbreast<T>, Data>;
  Judge judge{setup.criteria, setup.early_stop, run.drone[0].plant.Ts, {}, {}};
  judge.metrics.reset();
  EndDistance<T, ThreeAbreast<T>, Judge, Data> observe{judge};
  auto observeAndKeep = [&](const aurora_control::FormationObservation<T, ThreeAbreast<T>, Data>& o) {
    if (end) aurora_control::modelPositions<ThreeAbreast<T>, typename Law::Vehicle>(o.drones, end);
    return observe(o);
  };
  const long ticks = aurora_control::runFormation<Law, T, ThreeAbreast<T>, kCapacity>(run, setup.iterations,
                                                                                      observeAndKeep);
  return formationResult(judge.metrics, ticks, observe.distance);
}


// Every backend on the grid: runner, scalar loop and kernel threads the
// same bytes; SIMD lanes the same flags and ticks, metrics to `rel`. Over
// links the runner keys drone d's draws by d, as the sweep keys
// combination 0's: it is compared there.
template <class Law, typename T, bool Linked>
void expectEveryBackendAgrees(const Run3<double, typename Law::Data>& file, double loss_3, double rel) {
  const ThreeGrid grid(loss_3);
  const Setup3<T, Law> setup = setupOf<T>(file);
  ASSERT_EQ(setup.ideal_link, !Linked);
  const std::vector<SimResult> scalar = scalarLoop<Law, T, Linked>(setup, grid.view);
  for (long i = 0; i < (Linked ? 1 : grid.view.size()); ++i) {
    const SimResult r = runner<Law>(setup, grid.view, i);
    EXPECT_EQ(std::memcmp(&r, &scalar[i], sizeof r), 0) << "runner " << i;
  }
  EXPECT_EQ(differing(scalar, kernelThreads<Law, T, Linked>(setup, grid.view)), 0) << "kernel threads";
#ifdef AURORA_SWEEP_LANES
  test::expectRecordsAgree("simd lanes", scalar, simdLanes<Law>(setup, grid.view), rel, 8);
#endif
}

// Every backend, ideal and lossy, double and float.
template <class Law>
void expectEveryBackendAgrees(const Run3<double, typename Law::Data>& ideal,
                              const Run3<double, typename Law::Data>& lossy) {
  expectEveryBackendAgrees<Law, double, false>(ideal, std::nan(""), 1e-9);
  expectEveryBackendAgrees<Law, float, false>(ideal, std::nan(""), 2e-3);
  expectEveryBackendAgrees<Law, double, true>(lossy, 0.3, 1e-9);
  expectEveryBackendAgrees<Law, float, true>(lossy, 0.3, 2e-3);
}

// Undelayed (combination 0), the three end in their shape and the checks hold.
template <class Law>
void expectItFlies(const Run3<double, typename Law::Data>& ideal) {
  const ThreeGrid grid(std::nan(""));
  const Setup3<double, Law> setup = setupOf<double>(ideal);
  double end[9];
  const SimResult flown = runner<Law>(setup, grid.view, 0, end);
  const double want[9] = {0.5, 0.5, 1.5, 2.0, 0.5, 1.5, 0.5, 2.0, 1.5};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(end[i], want[i], 0.02) << i;
  EXPECT_TRUE(feasible(flown));
  FormationRecord record;
  std::memcpy(&record, &flown, sizeof record);
  EXPECT_NEAR(record.end_distance, 1.5, 0.02);  // the closest pair at the end: robots 1-2 and 1-3
  EXPECT_LT(record.min_distance, 1.0 + 1e-9);   // they started 1 m apart
  EXPECT_EQ(record.ticks, 1200);
  // Robot 3's delay reaches its run: delay_3 8 (combination 8) against 0.
  EXPECT_NE(std::memcmp(&flown, &scalarLoop<Law, double, false>(setup, grid.view)[8], sizeof flown), 0);
}

aurora_control::LinkParams lossyCrewLink() {
  aurora_control::LinkParams l;
  l.uplink.jitter = aurora_control::JitterKind::kUniform;
  l.uplink.jitter_max = 2;
  l.uplink.loss = 0.1;
  l.downlink.loss = 0.05;
  l.seed = 11;
  return l;
}

}  // namespace

TEST(ShapeConcept, AThreeRobotShapeFliesEveryBackend) {
  // Its parameters: three delays, then 2 x 9 gains, then 3 x 7 link values,
  // where the line has its gains and link values (no room is shared).
  EXPECT_EQ(kAt.delay(2), kLineLayout.k1(0));
  EXPECT_EQ(kAt.count(), kParamFirstLawGain);  // the room of the shapes; the laws' own gains follow
  const Run3<double> ideal = threeDrones(aurora_control::LinkParams());
  const ThreeGrid grid(std::nan(""));
  const Setup3<double, DroneLaw> setup = setupOf<double>(ideal);
  for (long i = 0; i < grid.view.size(); ++i) {  // each robot's delay and the gain reach its run
    const Combination c = grid.view.decode(i);
    const Run3<double> run = formationCombination<DroneLaw>(setup, c);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(run.drone[d].delay, long(c.v[kAt.delay(d)])) << i;
    EXPECT_EQ(run.gains.k1[3], c.v[kAt.k1(3)]);
  }
  // Robot 3's own uplink_loss_3 applies to robot 3 only.
  const Run3<double> lossy = threeDrones(lossyCrewLink());
  const Run3<double> own = formationCombination<DroneLaw>(setupOf<double>(lossy), ThreeGrid(0.3).view.decode(5));
  EXPECT_EQ(own.drone[2].link.uplink.loss, 0.3);
  EXPECT_EQ(own.drone[0].link.uplink.loss, 0.1);
  EXPECT_EQ(own.drone[1].link.uplink.loss, 0.1);

  // Three AR.Drones, and three of the test-only vehicle (point_mass.h):
  // the shape and the vehicle seams together.
  expectItFlies<DroneLaw>(ideal);
  expectEveryBackendAgrees<DroneLaw>(ideal, lossy);
  expectItFlies<PointLaw>(threePoints(aurora_control::LinkParams()));
  expectEveryBackendAgrees<PointLaw>(threePoints(aurora_control::LinkParams()), threePoints(lossyCrewLink()));
}

// Robots of different vehicles in one formation, each with its own law:
// their type is EitherLaw (either_law.h), which the generic code flies as
// any law. A crew of AR.Drones only flies as the AR.Drones' own formation,
// bit for bit, on the scalar loop, the kernel's threads and the SIMD lanes;
// a point mass between two AR.Drones flies every backend.
TEST(ShapeConcept, RobotsOfDifferentVehiclesFlyOneFormation) {
  const bool none[3] = {false, false, false}, middle[3] = {false, true, false};
  const ThreeGrid grid(std::nan(""));
  const std::vector<SimResult> own = scalarLoop<DroneLaw, double, false>(setupOf<double>(threeDrones({})), grid.view);
  const Setup3<double, MixedLaw> drones = setupOf<double>(mixedCrew(none, {}));
  EXPECT_EQ(differing(own, scalarLoop<MixedLaw, double, false>(drones, grid.view)), 0);
  EXPECT_EQ(differing(own, kernelThreads<MixedLaw, double, false>(drones, grid.view)), 0);
#ifdef AURORA_SWEEP_LANES
  EXPECT_EQ(differing(simdLanes<DroneLaw>(setupOf<double>(threeDrones({})), grid.view),
                      simdLanes<MixedLaw>(drones, grid.view)), 0);
#endif

  // The point mass is robot 2 (its velocities in X[3..5], nothing beyond).
  const Run3<double, MixedLaw> mixed = mixedCrew(middle, {});
  const Setup3<double, MixedLaw> setup = setupOf<double>(mixed);
  const aurora_control::FormationRun<double, ThreeAbreast<double>, MixedLaw> run =
      formationCombination<MixedLaw>(setup, grid.view.decode(0));
  // Each robot's own law's gains a sweep gives (robot_gains.h), named by
  // its law: the point mass's kp (robot 2), an AR.Drone's k1_x (robot 3).
  EXPECT_STREQ(RobotGains<MixedLaw>::rows(mixed.drone[1].plant)[0].name, "kp");
  EXPECT_STREQ(RobotGains<MixedLaw>::rows(mixed.drone[2].plant)[0].name, "k1_x");
  Combination c = grid.view.decode(0);
  c.v[robotGainParam(1, 0)] = 7.0, c.v[robotGainParam(2, 0)] = 0.25;
  const auto given = formationCombination<MixedLaw>(setup, c);
  EXPECT_EQ(given.drone[1].gains.second.kp, 7.0);
  EXPECT_EQ(given.drone[1].gains.second.kd, run.drone[1].gains.second.kd);
  EXPECT_EQ(given.drone[2].gains.first.underactuated.k1[0], 0.25);
  EXPECT_EQ(given.drone[0].gains.first.underactuated.k1[0], run.drone[0].gains.first.underactuated.k1[0]);
  EXPECT_EQ(given.drone[2].gains.second.kp, run.drone[2].gains.second.kp);  // a drone's unread point-mass gains
  long ticks = 0;
  auto pointOnly = [&](const aurora_control::FormationObservation<double, ThreeAbreast<double>, MixedLaw>& o) {
    for (int i = point_mass::PointMass::kStates; i < MixedLaw::Vehicle::kStates; ++i) {
      EXPECT_EQ(o.drones[1].model.X[i], 0.0) << "tick " << o.k << " state " << i;
    }
    ++ticks;
  };
  aurora_control::runFormation<MixedLaw, double, ThreeAbreast<double>, kCapacity>(run, 30, pointOnly);
  EXPECT_EQ(ticks, 30);
  expectItFlies<MixedLaw>(mixed);
  expectEveryBackendAgrees<MixedLaw>(mixed, mixedCrew(middle, lossyCrewLink()));
  EXPECT_NE(differing(own, scalarLoop<MixedLaw, double, false>(setup, grid.view)), 0);
}

// AuRoRA's triangle (aurora_control/formation/triangle/triangle_formation.h) is
// branch-free in the state: its variables, error and every law's velocities
// on SIMD lanes (this build's default instruction set, each lane its own
// triangle) equal the scalar code's, lane by lane, to rounding (xsimd's
// acos, atan and sqrt against libm's).
#ifdef AURORA_SWEEP_LANES
TEST(ShapeConcept, TheTriangleRunsOnSimdLanes) {
  using B = xsimd::batch<double, xsimd::default_arch>;
  constexpr int L = static_cast<int>(B::size);
  using Scalar = aurora_control::TriangleFormation<double>;
  using Lanes = aurora_control::TriangleFormation<B>;
  double X[L][9], Qd[L][9], v[L][9];
  for (int l = 0; l < L; ++l) {
    const double s = 0.1 * l;
    const double x[9] = {1 + s, 0.1 * s, 0.9, -0.8, -0.1 + s, 1.3 - s, 0.1, 1.2 + s, 1.1};
    for (int i = 0; i < 9; ++i) X[l][i] = x[i], v[l][i] = 0.1 * std::sin(1.0 + i + l);
    aurora_control::carrouselReference(2.0 * l, Qd[l]);
  }
  B Xb[9], Qdb[9], vb[9];
  for (int i = 0; i < 9; ++i) {
    alignas(64) double col[3][L];
    for (int l = 0; l < L; ++l) col[0][l] = X[l][i], col[1][l] = Qd[l][i], col[2][l] = v[l][i];
    Xb[i] = B::load_aligned(col[0]), Qdb[i] = B::load_aligned(col[1]), vb[i] = B::load_aligned(col[2]);
  }
  using aurora_control::TriangleLaw;
  for (TriangleLaw law : {TriangleLaw::kN, TriangleLaw::kPSO, TriangleLaw::kOSP}) {
    B Qb[9], eb[9], dXb[9];
    Lanes::variables(Xb, Qb);
    Lanes::error(Xb, Qdb, Qb, eb);
    Lanes::velocities(law, Xb, vb, dXb);
    for (int l = 0; l < L; ++l) {
      double Q[9], e[9], dX[9];
      Scalar::variables(X[l], Q);
      Scalar::error(X[l], Qd[l], Q, e);
      Scalar::velocities(law, X[l], v[l], dX);
      for (int i = 0; i < 9; ++i) {
        EXPECT_NEAR(Qb[i].get(l), Q[i], 1e-12) << "lane " << l << " Q " << i;
        EXPECT_NEAR(eb[i].get(l), e[i], 1e-12) << "lane " << l << " error " << i;
        EXPECT_NEAR(dXb[i].get(l), dX[i], 1e-11) << "lane " << l << " law " << int(law) << " dX " << i;
      }
    }
  }
}
#endif
