// flight --formation FILE for a triangle file (shape: triangle;
// docs/formation.md, "The triangle"): the one formation loop (triangle_run.h), one CSV
// row per layer period and the printed errors (RMS after 20 s, as the spec
// reports AuRoRA's).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_flight.h"
#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/triangle/triangle_yaml.h"

namespace aurora_control {

namespace {

// step (the layer's period n), t, each robot's position (kinematic: r{i}_x,
// y, z) or state and command (d{i}_), Q_ and Qd_ by the spec's names.
std::vector<std::string> triangleColumns(bool kinematic) {
  std::vector<std::string> c{"step", "t"};
  for (int d = 1; d <= 3; ++d) {
    const std::string p = (kinematic ? "r" : "d") + std::to_string(d) + "_";
    for (int i = 0; i < (kinematic ? 3 : TriangleDrone::kStates); ++i) c.push_back(p + TriangleDrone::stateName(i));
    for (int i = 0; !kinematic && i < TriangleDrone::kInputs; ++i) c.push_back(p + "u" + std::to_string(i + 1));
  }
  for (const char* q : {"Q_", "Qd_"}) {
    for (int i = 0; i < 9; ++i) c.push_back(q + std::string(Triangle::variableName(i)));
  }
  return c;
}

// Q of the robots' positions at period n (as the two-drone line's rows; the
// layer's own Q is of what the robots' links delivered).
void positionVariables(const TrianglePeriod& p, double X[9], double Q[9]) {
  for (int i = 0; i < 9; ++i) X[i] = p.position(i / 3, i % 3);
  Triangle::variables(X, Q);
}

std::vector<double> triangleRow(double t, bool kinematic, const TrianglePeriod& p) {
  std::vector<double> v{double(p.n), t};
  for (int d = 0; d < 3; ++d) {
    v.insert(v.end(), p.X[d], p.X[d] + (kinematic ? 3 : TriangleDrone::kStates));
    if (!kinematic) v.insert(v.end(), p.U[d], p.U[d] + TriangleDrone::kInputs);
  }
  double X[9], Q[9];
  positionVariables(p, X, Q);
  v.insert(v.end(), Q, Q + 9);
  v.insert(v.end(), p.layer.Qd(), p.layer.Qd() + 9);
  return v;
}

// Sums of squares after 20 s: the position (xF, yF, zF), p, q, beta, phi,
// theta, psi; the closest pair of robots (NaN from the first period a
// robot's position is NaN, as the formation checks take it).
struct TriangleErrors {
  double sq[7] = {}, closest = 1e300;
  long n = 0;
  void add(double t, const TrianglePeriod& p) {
    double X[9], Q[9], e[9];
    positionVariables(p, X, Q);
    closest = smallerDistance(closest, closestPair<Triangle>(X));
    if (t < kRmsFrom) return;
    Triangle::error(X, p.layer.Qd(), Q, e);
    sq[0] += e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    for (int i = 3; i < 9; ++i) sq[i - 2] += e[i] * e[i];
    ++n;
  }
  double rms(int i) const { return n > 0 ? std::sqrt(sq[i] / double(n)) : std::nan(""); }
};

}  // namespace

ShapedFlight TriangleShapeEntry::flyTable(const File& file, const FormationFlightOptions& o, FlightTable& table) {
  TriangleSetup setup = file;
  // Delays in drone steps (kinematic robots: in layer periods), shorter than
  // the run's steps (triangleSteps: what runTriangle flies, the node's rule).
  const double unit = setup.kinematic ? setup.period : setup.drone.Ts;
  const long samples = triangleSteps(setup);
  // --delay replaces the file's delays (its links' uplink delays, else 0).
  const std::vector<long> delays =
      robotDelays(o.delays, 3, "the triangle", unit, samples, {setup.delay[0], setup.delay[1], setup.delay[2]});
  for (int r = 0; r < 3; ++r) {
    setup.delay[r] = delays[r];
    refuseRobotDelay(setup.link[r], setup.delay[r], r, samples, unit);
  }
  TriangleErrors errors;
  const long periods = setup.periods();
  if (table.columns) table.columns(triangleColumns(setup.kinematic));
  ShapedFlight f;
  const auto t0 = std::chrono::steady_clock::now();
  withTriangleLaw(setup, [&](auto law) {
    flyTrianglePeriods<decltype(law)>(setup, [&](const TrianglePeriod& p) {
      const double t = double(p.n) * setup.period;
      errors.add(t, p);
      if (table.row) table.row(triangleRow(t, setup.kinematic, p));
    });
  });
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  char head[200], values[200], closest[40];
  std::snprintf(head, sizeof head, "flight: triangle, law %s, %s, %ld periods of %.3f s, delays %ld, %ld, %ld %s, in %.3f s\n",
                triangleLawName(setup.law), setup.kinematic ? "kinematic robots" : "three AR.Drones", periods,
                setup.period, setup.delay[0], setup.delay[1], setup.delay[2], setup.kinematic ? "periods" : "steps",
                f.seconds);
  std::snprintf(values, sizeof values, "position %.4f m, p %.4f m, q %.4f m, beta %.4f, phi %.4f, theta %.4f, psi %.4f rad",
                errors.rms(0), errors.rms(1), errors.rms(2), errors.rms(3), errors.rms(4), errors.rms(5), errors.rms(6));
  std::snprintf(closest, sizeof closest, "closest pair %.3f m", errors.closest);
  f.summary = head + rmsLine(errors.n, double(periods) * setup.period, values, closest);
  const char* names[7] = {"rms_position", "rms_p", "rms_q", "rms_beta", "rms_phi", "rms_theta", "rms_psi"};
  for (int i = 0; i < 7; ++i) f.errors.emplace_back(names[i], errors.rms(i));
  f.errors.emplace_back("closest", errors.closest);
  f.errors.emplace_back("periods", double(periods));
  for (int r = 0; r < 3; ++r) f.errors.emplace_back("delay_" + std::to_string(r + 1), double(setup.delay[r]));
  return f;
}

void TriangleShapeEntry::fly(const File& file, const FormationFlightOptions& o) { flyShapedToCsv<TriangleShapeEntry>(file, o); }

}  // namespace aurora_control
