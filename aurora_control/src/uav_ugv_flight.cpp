// flight --formation FILE for a UAV-UGV line file (shape: uav_ugv_line;
// docs/formation.md, "The UAV-UGV line"): the run of UavUgvLineFlight, its
// CSV and its printed errors (RMS after 20 s, as the spec reports AuRoRA's).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "aurora_control/formation/formation_flight.h"
#include "aurora_control/formation/uav_ugv_yaml.h"

namespace aurora_control {

namespace {

// step, t, the Pioneer's state and commands (r1_), the drone's (d2_), Q_ and
// Qd_ by the variables' names.
std::string uavUgvCsvHeader() {
  std::string h = "step,t";
  for (int i = 0; i < aurora_sim::Pioneer3dx::kStates; ++i) h += std::string(",r1_") + aurora_sim::Pioneer3dx::stateName(i);
  for (int i = 0; i < aurora_sim::Pioneer3dx::kInputs; ++i) h += ",r1_u" + std::to_string(i + 1);
  for (int i = 0; i < LawVehicle::kStates; ++i) h += std::string(",d2_") + LawVehicle::stateName(i);
  for (int i = 0; i < LawVehicle::kInputs; ++i) h += ",d2_u" + std::to_string(i + 1);
  for (const char* q : {"Q_", "Qd_"}) {
    for (int i = 0; i < 6; ++i) h += std::string(",") + q + UavUgvLine<double>::variableName(i);
  }
  return h + "\n";
}

void writeRow(FILE* f, long k, double t, const double* pioneer, const double* drone, const UavUgvLineFlight& run) {
  std::fprintf(f, "%ld,%.17g", k, t);
  for (int i = 0; i < aurora_sim::Pioneer3dx::kStates; ++i) std::fprintf(f, ",%.17g", pioneer[i]);
  for (int i = 0; i < 2; ++i) std::fprintf(f, ",%.17g", run.U_pioneer[i]);
  for (int i = 0; i < LawVehicle::kStates; ++i) std::fprintf(f, ",%.17g", drone[i]);
  for (int i = 0; i < 4; ++i) std::fprintf(f, ",%.17g", run.U_drone[i]);
  for (int i = 0; i < 6; ++i) std::fprintf(f, ",%.17g", run.layer.Q()[i]);
  for (int i = 0; i < 6; ++i) std::fprintf(f, ",%.17g", run.Qd[i]);
  std::fprintf(f, "\n");
}

// Sums of squares after 20 s: the formation position (xf, yf), rho, alpha,
// beta, the drone's distance to its desired position; the closest approach.
struct LineErrors {
  double sq[5] = {0, 0, 0, 0, 0}, closest = 1e300;
  long n = 0;
  void add(double t, const UavUgvLineFlight& run, const double* pioneer, const double* drone) {
    double d[3], de[3];
    for (int i = 0; i < 3; ++i) d[i] = drone[i] - pioneer[i], de[i] = run.layer.position(1)[i] - drone[i];
    closest = std::fmin(closest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    if (t < 20.0) return;
    const double* e = run.layer.Qtil();
    sq[0] += e[0] * e[0] + e[1] * e[1], sq[1] += e[3] * e[3], sq[2] += e[4] * e[4], sq[3] += e[5] * e[5];
    sq[4] += de[0] * de[0] + de[1] * de[1] + de[2] * de[2];
    ++n;
  }
  double rms(int i) const { return n > 0 ? std::sqrt(sq[i] / double(n)) : 0.0; }
};

}  // namespace

void flyUavUgvLine(const FormationFlightOptions& o) {
  UavUgvLineSetup setup = readUavUgvLineFile(o.formation, o.config_dir);
  const std::vector<long> delays = robotDelays(o.delays, 2, "the UAV-UGV line", setup.tick, setup.ticks(), {0, 0});
  for (int r = 0; r < 2; ++r) setup.delay[r] = delays[r];
  UavUgvLineFlight run(setup);
  LineErrors errors;
  aurora_sim::Pioneer3dx::State<double> pioneer;  // the states a tick starts from
  aurora_sim::Ardrone2::State<double> drone;
  const long ticks = setup.ticks();
  const double seconds = flyWithCsv(
      o.csv, uavUgvCsvHeader(), ticks,
      [&](long k) {
        pioneer = run.pioneer, drone = run.drone;
        run.tick(k);
        errors.add(double(k) * setup.tick, run, pioneer.X, drone.X);
      },
      [&](FILE* csv, long k) { writeRow(csv, k, double(k) * setup.tick, pioneer.X, drone.X, run); });
  std::printf("flight: UAV-UGV line (%s Pioneer + AR.Drone), %ld ticks of %.4f s, delays %ld and %ld ticks, in %.3f s\n",
              setup.pioneer.kinematic != 0.0 ? "kinematic" : "dynamic", ticks, setup.tick, setup.delay[0],
              setup.delay[1], seconds);
  std::printf("  RMS after 20 s: xf, yf %.4f m, rho %.4f m, alpha %.4f rad, beta %.4f rad, drone position %.4f m; "
              "closest approach %.3f m\n", errors.rms(0), errors.rms(1), errors.rms(2), errors.rms(3), errors.rms(4),
              errors.closest);
}

}  // namespace aurora_control
