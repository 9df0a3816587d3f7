// The line formation (docs/formation.md): the transforms and the laws'
// closed forms against the Jacobian and its pseudoinverses, and the lab's
// two-drone scenario against the reference values of the original code
// run with our start-up (the layer's first three periods, the first drone
// step, the RMS formation errors after 10 s of both laws).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <vector>

#include <fstream>
#include <iterator>
#include <type_traits>

#include "edited_file.h"
#include "aurora_control/formation/formation_controller.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_control/formation/line/line_yaml.h"
#include "aurora_control/formation/line/line_formation.h"
#include "aurora_control/formation/shapes.h"
#include "aurora_control/formation/uav_ugv/uav_ugv_line.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

using namespace aurora_control;
using Line = LineFormation<double>;

namespace {

// The lab's scenario (docs/formation.md, "The lab's two-drone scenario").
LineRun labScenario(FormationLaw law) {
  const auto vehicle = aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(std::string(AURORA_CONFIG_DIR) + "/vehicles/ardrone2.yaml");
  LineRun run;
  const double starts[2][3] = {{-1.0, 0.0, 0.75}, {1.0, 0.0, 1.0}};
  const double k1[6] = {0.1, 0.1, 5.0, 1.0, 1.0, 1.0}, k2[6] = {2.0, 2.0, 2.0, 20.0, 15.0, 2.5};
  for (int d = 0; d < 2; ++d) {
    run.drone[d].plant = run.drone[d].model = vehicle;
    for (int i = 0; i < 6; ++i) run.drone[d].gains.underactuated.k1[i] = k1[i], run.drone[d].gains.underactuated.k2[i] = k2[i];
    for (int i = 0; i < 3; ++i) run.drone[d].start[i] = starts[d][i];
  }
  run.law = law;
  run.reference.path = FormationPath::kLemniscate;
  run.reference.duration = 90.0;
  const double Q[6] = {0.0, 0.0, 1.0, 1.5, M_PI / 3.0, 0.0};
  for (int i = 0; i < 6; ++i) run.reference.Q[i] = Q[i];
  return run;
}

// dQ/dX by central differences (6 x 6).
Eigen::Matrix<double, 6, 6> numericJacobian(const double X[6]) {
  Eigen::Matrix<double, 6, 6> J;
  for (int j = 0; j < 6; ++j) {
    double a[6], b[6], Qa[6], Qb[6];
    for (int i = 0; i < 6; ++i) a[i] = b[i] = X[i];
    a[j] += 1e-6, b[j] -= 1e-6;
    Line::variables(a, Qa), Line::variables(b, Qb);
    for (int i = 0; i < 6; ++i) J(i, j) = (Qa[i] - Qb[i]) / 2e-6;
  }
  return J;
}

Eigen::MatrixXd pinv(const Eigen::MatrixXd& m) { return m.completeOrthogonalDecomposition().pseudoInverse(); }

}  // namespace

TEST(LineFormation, TransformsInvertEachOther) {
  const double X[6] = {-1.0, 0.0, 0.75, 1.0, 0.0, 1.0};
  double Q[6], back[6];
  Line::variables(X, Q);
  const double expected[6] = {-1.0, 0.0, 0.75, 2.01556444, 1.44644133, 0.0};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(Q[i], expected[i], 1e-8) << i;
  Line::positions(Q, back);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], X[i], 1e-12) << i;
  // Qd of the scenario: drone 2 at p1 + (1.299, 0, 0.75).
  const double Qd[6] = {0.0, 0.0, 1.0, 1.5, M_PI / 3.0, 0.0};
  Line::positions(Qd, back);
  EXPECT_NEAR(back[3], 1.5 * std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(back[5], 1.75, 1e-12);
}

// The closed forms (eq. F5-F7) are J^-1 v and the null-space laws'
// pseudoinverse formulas, above and below drone 1 (sigma signed).
TEST(LineFormation, LawsAreTheJacobianFormulas) {
  const double configs[2][6] = {{0.3, -0.2, 1.0, 1.1, 0.4, 1.9}, {0.3, -0.2, 1.9, 1.0, 0.5, 1.2}};
  const double v[6] = {0.11, -0.07, 0.05, 0.3, -0.2, 0.15};
  for (const auto& X : configs) {
    const Eigen::Matrix<double, 6, 6> J = numericJacobian(X);
    const Eigen::Map<const Eigen::Matrix<double, 6, 1>> vv(v);
    const Eigen::MatrixXd J1 = J.topRows(3), J2 = J.bottomRows(3);
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(6, 6);
    const Eigen::VectorXd n = J.inverse() * vv;
    const Eigen::VectorXd p = pinv(J1) * vv.head(3) + (I - pinv(J1) * J1) * pinv(J2) * vv.tail(3);
    const Eigen::VectorXd s = (I - pinv(J2) * J2) * pinv(J1) * vv.head(3) + pinv(J2) * vv.tail(3);
    const std::pair<FormationLaw, Eigen::VectorXd> expected[3] = {
        {FormationLaw::kInverseKinematics, n}, {FormationLaw::kPositionPriority, p}, {FormationLaw::kShapePriority, s}};
    for (const auto& e : expected) {
      double dX[6];
      Line::velocities(e.first, X, v, dX);
      for (int i = 0; i < 6; ++i) EXPECT_NEAR(dX[i], e.second(i), 1e-7) << int(e.first) << " " << i << " z " << X[5];
    }
  }
}

// The layer's first periods and the first drone step of the lab's scenario
// (law 'P', no delay), to the reference's 9 digits.
TEST(LineFormation, TheLabScenarioStartsAsTheReference) {
  struct Period {
    long k;
    double Q[6], dQd[6], dXr[6], Xr[6];
  };
  std::vector<Period> periods;
  double z1 = 0, z2 = 0, u1 = 0, u2 = 0;
  auto observe = [&](const LineObservation& o) {
    if (o.k == 0) {
      z1 = o.drones[0].model.X[aurora_sim::kZ], z2 = o.drones[1].model.X[aurora_sim::kZ];
      u1 = o.steps[0].U[2], u2 = o.steps[1].U[2];
    }
    if (!o.layer_ran) return;
    Period p{o.k, {}, {}, {}, {}};
    for (int i = 0; i < 6; ++i) {
      p.Q[i] = o.layer.Q()[i], p.dQd[i] = o.layer.dQd()[i];
      p.dXr[i] = o.layer.velocity(i / 3)[i % 3], p.Xr[i] = o.layer.position(i / 3)[i % 3];
    }
    periods.push_back(p);
  };
  runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(labScenario(FormationLaw::kPositionPriority), 13, observe);
  ASSERT_EQ(periods.size(), 3u);
  const auto near = [](const double* got, std::initializer_list<double> want, const char* what, long k) {
    int i = 0;
    for (double w : want) {
      EXPECT_NEAR(got[i], w, 1e-9 + 1e-8 * std::fabs(w)) << what << "[" << i << "] at k = " << k;
      ++i;
    }
  };
  near(periods[0].dXr, {0.0462117157, 0, 0.124353002, -0.100069673, 0, 0.0380088919}, "dXr", 0);
  near(periods[0].Xr, {-0.990757657, 0, 0.7748706, 0.979986065, 0, 1.00760178}, "Xr", 0);
  near(periods[0].dQd, {0, 0, 0, 0, 0, 0}, "dQd", 0);
  near(periods[1].Q, {-0.999983507, 0, 0.747447362, 2.01461866, 1.45003626, 0}, "Q", 6);
  near(periods[1].dQd, {4.6473162e-4, 9.29463237e-4, 0, 0, 0, 0}, "dQd", 6);
  near(periods[1].dXr, {0.0466794536, 9.38757869e-4, 0.125609384, -0.0998186762, 0, 0.038809912}, "dXr", 6);
  near(periods[1].Xr, {-0.981421766, 1.87751574e-4, 0.799992477, 0.96002233, 0, 1.01536376}, "Xr", 6);
  near(periods[2].dQd, {0.00139143677, 0.00278287329, 0, 0, 0, 0}, "dQd", 12);
  near(periods[2].dXr, {0.047609169, 0.00281997563, 0.111239667, -0.0990550789, 4.58924212e-8, 0.0409489385}, "dXr", 12);
  EXPECT_NEAR(z1, 0.7458055931, 1e-10);
  EXPECT_NEAR(z2, 0.995805491, 1e-9);
  EXPECT_NEAR(u1, 0.7777726053, 1e-10);
  EXPECT_NEAR(u2, 0.7488916725, 1e-10);
}

// The whole 90 s scenario: RMS formation errors after 10 s and the
// smallest distance, both laws, against the original's (3 digits). The
// error at tick k is the layer's held Qd against Q of the positions X_k
// (docs/formation.md, "Formation errors").
TEST(LineFormation, BothLawsFlyTheLabScenarioAsTheOriginal) {
  struct Want {
    FormationLaw law;
    double rho, alpha, beta, position, z, closest;
  };
  const Want wants[2] = {{FormationLaw::kPositionPriority, 0.290, 0.286, 0.426, 0.238, 0.000, 1.22},
                         {FormationLaw::kInverseKinematics, 0.026, 0.025, 0.000, 0.238, 0.000, 1.33}};
  for (const Want& w : wants) {
    double sum[5] = {}, closest = 1e9, X[6];
    long n = 0;
    auto observe = [&](const LineObservation& o) {
      for (int d = 0; d < 2; ++d) {
        for (int i = 0; i < 3; ++i) X[3 * d + i] = o.X_before[d][i];
      }
      if (o.k / 30.0 >= 10.0) {
        double Q[6], e[6];
        Line::variables(X, Q);
        for (int i = 0; i < 6; ++i) e[i] = o.layer.Qd()[i] - Q[i];
        const double terms[5] = {e[3] * e[3], e[4] * e[4], e[5] * e[5], e[0] * e[0] + e[1] * e[1], e[2] * e[2]};
        for (int i = 0; i < 5; ++i) sum[i] += terms[i];
        ++n;
      }
      for (int d = 0; d < 2; ++d) {
        for (int i = 0; i < 3; ++i) X[3 * d + i] = o.drones[d].model.X[i];
      }
      closest = std::min(closest, std::sqrt((X[0] - X[3]) * (X[0] - X[3]) + (X[1] - X[4]) * (X[1] - X[4]) +
                                            (X[2] - X[5]) * (X[2] - X[5])));
    };
    runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(labScenario(w.law), 2700, observe);
    double rms[5];
    for (int i = 0; i < 5; ++i) rms[i] = std::sqrt(sum[i] / n);
    std::printf("law %d: RMS after 10 s rho %.4f m, alpha %.4f rad, beta %.4f rad, position %.4f m, z %.4f m; "
                "closest %.3f m\n", int(w.law), rms[0], rms[1], rms[2], rms[3], rms[4], closest);
    const double* got[5] = {&rms[0], &rms[1], &rms[2], &rms[3], &rms[4]};
    const double want[5] = {w.rho, w.alpha, w.beta, w.position, w.z};
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(*got[i], want[i], 0.0006) << "law " << int(w.law) << " error " << i;
    EXPECT_NEAR(closest, w.closest, 0.006);
  }
}

// Per-drone delay: the layer sees each drone through its own uplink (delay
// rule): at a period k, Q is that of drone 1's position at k - d1 and drone
// 2's at k - d2, exactly.
TEST(LineFormation, TheLayerSeesEachDroneThroughItsOwnDelay) {
  LineRun run = labScenario(FormationLaw::kPositionPriority);
  run.drone[0].delay = 3, run.drone[1].delay = 9;
  std::vector<std::vector<double>> X(1, std::vector<double>{-1.0, 0.0, 0.75, 1.0, 0.0, 1.0});
  long checked = 0, differ = 0;
  auto observe = [&](const LineObservation& o) {
    if (o.layer_ran && o.k >= 9) {
      const long a = o.k - 3, b = o.k - 9;
      const double seen[6] = {X[a][0], X[a][1], X[a][2], X[b][3], X[b][4], X[b][5]};
      double Q[6];
      Line::variables(seen, Q);
      for (int i = 0; i < 6; ++i) differ += Q[i] != o.layer.Q()[i];
      ++checked;
    }
    std::vector<double> now(6);
    for (int d = 0; d < 2; ++d) {
      for (int i = 0; i < 3; ++i) now[3 * d + i] = o.drones[d].model.X[i];
    }
    X.push_back(now);
  };
  runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(run, 600, observe);
  EXPECT_GT(checked, 90);
  EXPECT_EQ(differ, 0);
  // Not vacuous: with the delays the formation flies differently.
  double last_delayed[6], last_plain[6];
  for (int i = 0; i < 6; ++i) last_delayed[i] = X.back()[i];
  X.assign(1, std::vector<double>(6, 0.0));
  runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(labScenario(FormationLaw::kPositionPriority), 600, observe);
  for (int i = 0; i < 6; ++i) last_plain[i] = X.back()[i];
  double gap = 0;
  for (int i = 0; i < 6; ++i) gap += std::fabs(last_delayed[i] - last_plain[i]);
  EXPECT_GT(gap, 1e-3);
}

// The shipped formation files are the lab's scenario with each law; bad
// files are refused naming the key and what is accepted.
TEST(FormationFile, ShippedFilesAreTheLabScenario) {
  const std::string config = AURORA_CONFIG_DIR;
  const auto vehicle = aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(config + "/vehicles/ardrone2.yaml");
  const std::pair<const char*, FormationLaw> files[2] = {{"line_lemniscate", FormationLaw::kPositionPriority},
                                                         {"line_lemniscate_ik", FormationLaw::kInverseKinematics}};
  for (const auto& f : files) {
    const FormationFile file = readFormationFile(config + "/formations/" + f.first + ".yaml", config);
    const LineRun shipped = formationRun(file, vehicle);
    EXPECT_EQ(shipped.schedule.period_ticks, 6);
    EXPECT_EQ(shipped.schedule.step_ticks, 1);
    std::vector<double> a, b;
    auto record = [](std::vector<double>& into) {
      return [&into](const LineObservation& o) {
        for (int d = 0; d < 2; ++d) into.insert(into.end(), o.drones[d].model.X, o.drones[d].model.X + 12);
      };
    };
    auto ra = record(a), rb = record(b);
    runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(shipped, 300, ra);
    runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(labScenario(f.second), 300, rb);
    EXPECT_EQ(a, b) << f.first;
  }
}

TEST(FormationFile, MistakesAreRefusedNamingTheKey) {
  const std::string config = AURORA_CONFIG_DIR;
  std::ifstream in(config + "/formations/line_lemniscate.yaml");
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto refusal = [](const std::string& from, const std::string& to) {
    return aurora_tests::refusalOfEditedFile("formations/line_lemniscate.yaml", from, to,
                                             [](const std::string& path, const std::string& config) {
                                               readFormationFile(path, config);
                                             });
  };
  const auto says = [&](const std::string& from, const std::string& to, const std::string& text) {
    const std::string why = refusal(from, to);
    EXPECT_NE(why.find(text), std::string::npos) << to << " -> " << why;
  };
  // The shapes' list reads the shape first and names every shape it knows.
  const std::string hexagon = aurora_tests::refusalOfEditedFile(
      "formations/line_lemniscate.yaml", "shape: line", "shape: hexagon",
      [](const std::string& path, const std::string& config) {
        withFormationFile(path, config, "", [](auto, const auto&) {});
      });
  EXPECT_NE(hexagon.find("'formation.shape' = 'hexagon' is unknown: accepted line, uav_ugv_line, triangle"),
            std::string::npos) << hexagon;
  says("shape: line", "shape: hexagon", "'formation.shape' = 'hexagon' is not the two-drone line this reader reads");
  // AuRoRA's shapes have readers of their own; this one says so.
  for (const char* name : {"triangle_ardrones", "line_pioneer_ardrone"}) {
    try {
      readFormationFile(config + "/formations/" + name + ".yaml", config);
      ADD_FAILURE() << name << " read as a two-drone line";
    } catch (const aurora_common::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("is not the two-drone line this reader reads"), std::string::npos) << e.what();
    }
  }
  says("law: position_priority", "law: P", "'formation.law' = 'P' is unknown: accepted inverse_kinematics, position_priority");
  says("{rho: 1.5,", "{rho: 0,", "'formation.reference.shape.rho' = 0 is refused: accepted a distance > 0 m");
  says("beta: 0.0}", "beta: 1.0}", "sin^2 alpha + sin^2 beta = 1.458");
  says("    - namespace: ardrone2", "    - namespace: ardrone1", "'formation.drones[1].namespace' = 'ardrone1' is drone 1's too");
  says("  period: 0.2", "  periods: 0.2", "'formation.periods' is not a known key");
  says("      delay: 0\n      controller: *lab_gains", "      delay: -2\n      controller: *lab_gains",
       "'formation.drones[1].delay' = -2");
  says("start: [1.0, 0.0, 1.0]", "start: [1.0, 0.0, 0.75]", "0 m apart in height: the line's variables are singular");
  says("start: [1.0, 0.0, 1.0]", "start: [1.0, 0.0, -0.1]", "'formation.drones[1].start' = [1, 0, -0.1] has z = -0.1 m, below the ground: accepted heights [0, 100] m");
  says("  period: 0.2", "  period: 0.2\n  period: 0.4", "'formation.period' is given twice, on lines 12 and 13");
  says("k1: [0.1, 0.1, 1.0, 0.75, 0.5, 0.5]", "k1: [0.1, 0.1, 1.0, 0.75, 0.5, 500]",
       "'formation.gains.k1' = 500 (entry 6) is refused: accepted gains in [0.001, 100]");
  const std::string one = good.substr(0, good.find("    - namespace: ardrone2"));
  const std::string path = ::testing::TempDir() + "/one_drone.yaml";
  std::ofstream(path) << one;
  try {
    readFormationFile(path, config);
    ADD_FAILURE() << "one drone accepted";
  } catch (const aurora_common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("'formation.drones' must list the line's 2 drones (it lists 1)"), std::string::npos) << e.what();
  }
  const auto vehicle = aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(config + "/vehicles/ardrone2.yaml");
  FormationFile f = readFormationFile(config + "/formations/line_lemniscate.yaml", config);
  f.period = 0.25;
  try {
    formationRun(f, vehicle);
    ADD_FAILURE() << "a period of 7.5 steps accepted";
  } catch (const aurora_common::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("accepted a whole number of drone steps"), std::string::npos) << e.what();
  }
}

// Each drone over its own link model: a link that draws but changes nothing
// is the delay rule bit for bit; a lossy link changes the flight, the same
// way every run; two drones over one link file lose different packets.
TEST(LineFormation, EachDroneFliesOverItsOwnLink) {
  const auto record = [](const LineRun& run) {
    std::vector<double> out;
    auto observe = [&](const LineObservation& o) {
      for (int d = 0; d < 2; ++d) out.insert(out.end(), o.drones[d].model.X, o.drones[d].model.X + 12);
    };
    runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(run, 900, observe);
    return out;
  };
  LineRun plain = labScenario(FormationLaw::kInverseKinematics);
  plain.drone[0].delay = 2, plain.drone[1].delay = 5;
  LineRun drawing = plain;
  for (int d = 0; d < 2; ++d) drawing.drone[d].link.uplink.jitter = JitterKind::kUniform;  // max 0: no effect
  ASSERT_FALSE(drawing.drone[0].link.ideal());
  EXPECT_EQ(record(plain), record(drawing));
  LineRun lossy = plain;
  for (int d = 0; d < 2; ++d) {
    lossy.drone[d].link.uplink.loss = 0.3, lossy.drone[d].link.downlink.loss = 0.3, lossy.drone[d].link.downlink.delay = 1;
  }
  const std::vector<double> a = record(lossy), b = record(lossy);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, record(plain));
  // The same link on both drones, drawn per drone: the uplinks lose different states.
  ModelLink<64, double> first(lossy.drone[0].link, 0, 0, 1.0 / 30.0), second(lossy.drone[1].link, 0, 1, 1.0 / 30.0);
  long differ = 0;
  for (long k = 0; k < 300; ++k) differ += first.uplinkIndex(k) != second.uplinkIndex(k);
  EXPECT_GT(differ, 30);
}

// The formation node's core (formation_controller.h) fed the drones' states
// of the offline runner answers every tick with the runner's commands, bit
// for bit: each drone's delay, drone 2 over a lossy, jittery link (its draws
// keyed by the drone, as the runner's), the layer's Q and Qd.
TEST(FormationController, IsTheRunnersTickOverDelaysAndLinks) {
  LineRun run = labScenario(FormationLaw::kInverseKinematics);
  run.drone[0].delay = 3, run.drone[1].delay = 9;
  run.drone[1].link = readLinkFile(std::string(AURORA_CONFIG_DIR) + "/links/wifi_congested.yaml");
  run.drone[1].link.uplink.delay = 9;  // the drone's delay is its link's uplink delay
  struct Tick {
    double X[2][12], U[2][4], Q[6], Qd[6];
  };
  std::vector<Tick> offline;
  auto observe = [&](const LineObservation& o) {
    Tick t;
    for (int d = 0; d < 2; ++d) {
      for (int i = 0; i < 12; ++i) t.X[d][i] = o.X_before[d][i];
      for (int i = 0; i < 4; ++i) t.U[d][i] = o.steps[d].U[i];
    }
    for (int i = 0; i < 6; ++i) t.Q[i] = o.layer.Q()[i], t.Qd[i] = o.layer.Qd()[i];
    offline.push_back(t);
  };
  runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(run, 900, observe);
  FormationController<64, aurora_control::LineFormation<double>, aurora_control::LawSettings<aurora_control::ArdroneLawData>> core(run, aurora_control::LawSettings<aurora_control::ArdroneLawData>::flying<aurora_control::ArdroneLaw<LawType::kUnderactuated>>());
  long mismatches = 0, hovers = 0;
  for (long k = 0; k < 900; ++k) {
    for (int d = 0; d < 2; ++d) {
      StateSample s;
      s.step = k;
      for (int i = 0; i < 12; ++i) s.X[i] = offline[k].X[d][i];
      ASSERT_TRUE(core.push(d, s));
    }
    ASSERT_EQ(core.commonStep(), k);
    const auto t = core.tick(k);
    EXPECT_EQ(t.layer_ran, k % 6 == 0);
    for (int d = 0; d < 2; ++d) {
      mismatches += std::memcmp(t.out[d].U, offline[k].U[d], sizeof offline[k].U[d]) != 0;
      hovers += t.out[d].drone_hovers;
    }
    mismatches += std::memcmp(core.layer().Q(), offline[k].Q, sizeof offline[k].Q) != 0;
    mismatches += std::memcmp(core.layer().Qd(), offline[k].Qd, sizeof offline[k].Qd) != 0;
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(hovers, 0) << "drone 2's congested link never made it hover: not a link test";
}

// Issue 31: drones that start level (or together) make the line singular
// (eq. F4 divides by z2 - z1): the runner flies NaN; every formation check
// then fails and the figures show NaN (not "shape error max 0", not a
// smallest distance of 1e30), and the node's core never hands a
// non-finite command to a drone: every drone hovers instead.
TEST(FormationChecks, ADroneFlyingNaNFailsEveryCheck) {
  for (const double level_z : {0.75, 0.0}) {
    LineRun run = labScenario(FormationLaw::kPositionPriority);
    run.drone[1].start[2] = run.drone[0].start[2] = level_z;
    if (level_z == 0.0) run.drone[1].start[0] = run.drone[0].start[0];  // at the same point: rho = 0
    FormationMetrics<double, bool, Line> m;
    m.reset();
    const auto criteria = FormationCriteria<double>::study();
    bool nan_seen = false;
    auto observe = [&](const LineObservation& o) {
      double X[6], Xd[6];
      for (int d = 0; d < 2; ++d) {
        for (int i = 0; i < 3; ++i) X[3 * d + i] = o.X_before[d][i];
      }
      Line::positions(o.layer.Qd(), Xd);
      m.add(criteria, X, Xd, double(o.k) * run.drone[0].plant.Ts, run.drone[0].plant.Ts);
      nan_seen = nan_seen || std::isnan(o.steps[1].U[0]);
    };
    runFormation<aurora_control::ArdroneLaw<LawType::kUnderactuated>, double, Line, 64>(run, 600, observe);
    ASSERT_TRUE(nan_seen) << "the level start did not fly NaN: no test of the checks";
    for (int i = 0; i < 4; ++i) EXPECT_FALSE(m.ok[i]) << "check " << i + 1 << " passed a NaN drone";
    EXPECT_FALSE(m.feasible());
    EXPECT_TRUE(std::isnan(m.max_shape)) << m.max_shape;
    EXPECT_TRUE(std::isnan(m.closest)) << m.closest;
  }
}

// The smallest distance of three robots is NaN whichever robot is NaN (a
// finite pair checked after a NaN one took its place: robot 1 NaN gave the
// distance of robots 2 and 3), and stays NaN over a flight.
struct ThreeRobots {
  static constexpr int kDrones = 3, kVariables = 9;
};
TEST(FormationChecks, TheClosestPairIsNaNWhicheverRobotIsNaN) {
  for (int nan_robot = 0; nan_robot < 3; ++nan_robot) {
    double X[9] = {0, 0, 1, 2, 0, 1, 0, 3, 1};
    EXPECT_DOUBLE_EQ(closestPair<ThreeRobots>(X), 2.0);
    X[3 * nan_robot + 1] = std::nan("");
    EXPECT_TRUE(std::isnan(closestPair<ThreeRobots>(X))) << "robot " << nan_robot + 1;
  }
  EXPECT_TRUE(std::isnan(smallerDistance(smallerDistance(5.0, std::nan("")), 1.0)));
  EXPECT_DOUBLE_EQ(smallerDistance(smallerDistance(5.0, 2.0), 3.0), 2.0);
}

TEST(FormationController, ANonFiniteCommandMakesEveryDroneHover) {
  LineRun run = labScenario(FormationLaw::kPositionPriority);
  run.drone[1].start[2] = run.drone[0].start[2];  // level: the layer commands NaN
  FormationController<64, aurora_control::LineFormation<double>, aurora_control::LawSettings<aurora_control::ArdroneLawData>> core(run, aurora_control::LawSettings<aurora_control::ArdroneLawData>::flying<aurora_control::ArdroneLaw<LawType::kUnderactuated>>());
  for (int d = 0; d < 2; ++d) {
    StateSample s;
    s.step = 0;
    for (int i = 0; i < 12; ++i) s.X[i] = 0.0;
    for (int i = 0; i < 3; ++i) s.X[aurora_sim::kX + i] = run.drone[d].start[i];
    ASSERT_TRUE(core.push(d, s));
  }
  const auto t = core.tick(0);
  EXPECT_EQ(t.not_finite, 1) << "drone 2's command was not reported as non-finite";
  for (int d = 0; d < 2; ++d) {
    for (int i = 0; i < 4; ++i) EXPECT_EQ(t.out[d].U[i], 0.0) << "drone " << d + 1 << " does not hover";
  }
  // The shipped start (drone 2 0.25 m above) flies finite commands.
  FormationController<64, aurora_control::LineFormation<double>, aurora_control::LawSettings<aurora_control::ArdroneLawData>> fine(labScenario(FormationLaw::kPositionPriority), aurora_control::LawSettings<aurora_control::ArdroneLawData>::flying<aurora_control::ArdroneLaw<LawType::kUnderactuated>>());
  for (int d = 0; d < 2; ++d) {
    StateSample s;
    s.step = 0;
    for (int i = 0; i < 12; ++i) s.X[i] = 0.0;
    for (int i = 0; i < 3; ++i) s.X[aurora_sim::kX + i] = labScenario(FormationLaw::kPositionPriority).drone[d].start[i];
    ASSERT_TRUE(fine.push(d, s));
  }
  EXPECT_EQ(fine.tick(0).not_finite, -1);
}

// A shape's own parts are its members, found by the generic runner with no
// list of shapes: a moving reference (ownReference, FormationPath::kOwn) and
// a layer (Layer); a shape without them keeps the integrating layer, and
// never a reference of its own (NaN: no check passes).
namespace {
struct RisingLine : LineFormation<double> {
  template <typename V>
  static void ownReference(const V& t, V Qd[kVariables]) {
    for (int i = 0; i < kVariables; ++i) Qd[i] = V(i) + t;
  }
  template <typename V>
  using Layer = FormationLayer<V, LineFormation<V>>;  // a stand-in: any type the shape names
};
}  // namespace

TEST(FormationParts, AShapesOwnReferenceAndLayerAreItsMembers) {
  FormationReference<double, RisingLine> own;
  own.path = FormationPath::kOwn;
  double Qd[6];
  own.at(2.0, Qd);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(Qd[i], i + 2.0);
  FormationReference<double, Line> none;
  none.path = FormationPath::kOwn;
  none.at(2.0, Qd);
  for (double q : Qd) EXPECT_TRUE(std::isnan(q));
  none.path = FormationPath::kFixed;
  none.Q[2] = 1.5;
  none.at(2.0, Qd);
  EXPECT_EQ(Qd[2], 1.5);
  static_assert(std::is_same<LayerOf<float, RisingLine>, FormationLayer<float, LineFormation<float>>>::value,
                "the shape's own layer, in the asked precision");
  static_assert(std::is_same<LayerOf<double, Line>, FormationLayer<double, Line>>::value, "the integrating layer");
  static_assert(std::is_same<LayerOf<double, UavUgvLine<double>>, UavUgvLayer<double>>::value, "the UAV-UGV line's");
}
