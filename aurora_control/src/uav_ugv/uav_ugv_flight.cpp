// flight --formation FILE for a UAV-UGV line file (shape: uav_ugv_line;
// docs/formation.md, "The UAV-UGV line"): the one formation loop (uav_ugv_run.h), its
// CSV and its printed errors (RMS after 20 s, as the spec reports AuRoRA's).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_flight.h"
#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/uav_ugv/uav_ugv_yaml.h"

namespace aurora_control {

namespace {

// step, t, the ground robot's state and commands (r1_), the drone's (d2_), Q_ and
// Qd_ by the variables' names.
std::vector<std::string> uavUgvColumns() {
  std::vector<std::string> c{"step", "t"};
  for (int i = 0; i < UavUgvGround::kStates; ++i) c.push_back(std::string("r1_") + UavUgvGround::stateName(i));
  for (int i = 0; i < UavUgvGround::kInputs; ++i) c.push_back("r1_u" + std::to_string(i + 1));
  for (int i = 0; i < UavUgvDrone::kStates; ++i) c.push_back(std::string("d2_") + UavUgvDrone::stateName(i));
  for (int i = 0; i < UavUgvDrone::kInputs; ++i) c.push_back("d2_u" + std::to_string(i + 1));
  for (const char* q : {"Q_", "Qd_"}) {
    for (int i = 0; i < 6; ++i) c.push_back(q + std::string(UavUgvLine<double>::variableName(i)));
  }
  return c;
}

using Tick = FormationObservation<double, UavUgvShape, UavUgvRobots::Data>;

// Q of the robots' positions at tick k's start (X_k, as the two-drone
// line's rows; the layer's own Q is of what the robots' links delivered).
void positionVariables(const Tick& o, double Q[6]) {
  double X[6];
  dronePositions<UavUgvShape, UavUgvRobots::Vehicle>(o.X_before, X);
  UavUgvShape::variables(X, Q);
}

// Tick k's row: the robots' states at its start, the commands they
// applied, Q of their positions and the layer's Qd.
std::vector<double> uavUgvRow(double t, const Tick& o) {
  std::vector<double> v{double(o.k), t};
  v.insert(v.end(), o.X_before[0], o.X_before[0] + UavUgvGround::kStates);
  v.insert(v.end(), o.steps[0].U, o.steps[0].U + UavUgvGround::kInputs);
  v.insert(v.end(), o.X_before[1], o.X_before[1] + UavUgvDrone::kStates);
  v.insert(v.end(), o.steps[1].U, o.steps[1].U + UavUgvDrone::kInputs);
  double Q[6];
  positionVariables(o, Q);
  v.insert(v.end(), Q, Q + 6);
  v.insert(v.end(), o.layer.Qd(), o.layer.Qd() + 6);
  return v;
}

// Sums of squares after 20 s: the formation position (xf, yf), rho, alpha,
// beta, the drone's distance to its desired position. (The closest approach
// is the judge's: FormationMetrics::closest, NaN once a robot's is.)
struct LineErrors {
  double sq[5] = {0, 0, 0, 0, 0};
  long n = 0;
  void add(double t, const Tick& o) {
    if (t < kRmsFrom) return;
    const double* drone = o.X_before[1];
    double de[3];
    for (int i = 0; i < 3; ++i) de[i] = o.layer.position(1)[i] - drone[i];
    double Q[6], e[6];
    positionVariables(o, Q);
    UavUgvShape::error(nullptr, o.layer.Qd(), Q, e);
    sq[0] += e[0] * e[0] + e[1] * e[1], sq[1] += e[3] * e[3], sq[2] += e[4] * e[4], sq[3] += e[5] * e[5];
    sq[4] += de[0] * de[0] + de[1] * de[1] + de[2] * de[2];
    ++n;
  }
  double rms(int i) const { return n > 0 ? std::sqrt(sq[i] / double(n)) : std::nan(""); }
};

}  // namespace

ShapedFlight UavUgvShapeEntry::flyTable(const File& file, const FormationFlightOptions& o, FlightTable& table) {
  UavUgvLineSetup setup = file;
  // --delay replaces the file's delays (its links' uplink delays, else 0).
  const std::vector<long> delays =
      robotDelays(o.delays, 2, "the UAV-UGV line", setup.tick, setup.ticks(), {setup.delay[0], setup.delay[1]});
  for (int r = 0; r < 2; ++r) {
    setup.delay[r] = delays[r];
    refuseRobotDelay(setup.link[r], setup.delay[r], r, setup.ticks(), setup.tick);
  }
  LineErrors errors;
  FormationJudge<double, UavUgvShape, UavUgvRobots::Data> judge{FormationCriteria<double>::study(), false, setup.tick,
                                                                {}, {}};
  judge.metrics.reset();
  const long ticks = setup.ticks();
  if (table.columns) table.columns(uavUgvColumns());
  ShapedFlight f;
  const auto t0 = std::chrono::steady_clock::now();
  auto observe = [&](const Tick& o) {
    const double t = double(o.k) * setup.tick;
    errors.add(t, o);
    judge(o);
    if (table.row) table.row(uavUgvRow(t, o));
  };
  runFormation<UavUgvRobots, double, UavUgvShape, kDelayHistory>(uavUgvRun(setup), ticks, observe);
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  char head[200], values[200], closest[40];
  std::snprintf(head, sizeof head,
                "flight: UAV-UGV line (%s %s + %s), %ld ticks of %.4f s, delays %ld and %ld ticks, in %.3f s\n",
                setup.ground.kinematic != 0.0 ? "kinematic" : "dynamic", UavUgvGround::name(),
                UavUgvDrone::name(), ticks, setup.tick, setup.delay[0],
                setup.delay[1], f.seconds);
  std::snprintf(values, sizeof values, "xf, yf %.4f m, rho %.4f m, alpha %.4f rad, beta %.4f rad, drone position %.4f m",
                errors.rms(0), errors.rms(1), errors.rms(2), errors.rms(3), errors.rms(4));
  std::snprintf(closest, sizeof closest, "closest approach %.3f m", judge.metrics.closest);
  f.summary = head + rmsLine(errors.n, double(ticks) * setup.tick, values, closest) +
              checksText(judge.criteria, judge.metrics, true);
  f.errors = {{"rms_xf_yf", errors.rms(0)}, {"rms_rho", errors.rms(1)}, {"rms_alpha", errors.rms(2)},
              {"rms_beta", errors.rms(3)}, {"rms_drone_position", errors.rms(4)}, {"closest", judge.metrics.closest},
              {"ticks", double(ticks)}, {"delay_1", double(setup.delay[0])}, {"delay_2", double(setup.delay[1])}};
  // The formation checks, as a sweep records them (check_1 .. check_5: 1 held).
  const FormationMetrics<double, bool, UavUgvShape>& m = judge.metrics;
  for (int i = 0; i < m.kChecks; ++i) f.errors.emplace_back("check_" + std::to_string(i + 1), m.ok[i] ? 1.0 : 0.0);
  f.errors.emplace_back("feasible", m.feasible() ? 1.0 : 0.0);
  f.errors.emplace_back("ground_command", m.ground_command);
  return f;
}

void UavUgvShapeEntry::fly(const File& file, const FormationFlightOptions& o) { flyShapedToCsv<UavUgvShapeEntry>(file, o); }

}  // namespace aurora_control
