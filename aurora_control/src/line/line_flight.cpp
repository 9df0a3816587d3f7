// The two-drone line's flight (line_flight.h): flight --formation with a
// line's file, its CSV, its formation errors and checks.
#include "aurora_control/formation/line/line_flight.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "aurora_common/number_text.h"
#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/params/shipped_files.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace aurora_control {

namespace {

using Line = LineFormation<double>;

// The formation errors (docs/formation.md, "Formation errors"): at every
// tick k from 10 s on, the layer's held Qd against Q of the positions X_k;
// RMS of rho, alpha, beta, the formation's horizontal position and height.
class FormationErrors {
 public:
  void add(const LineObservation& o, double Ts) {
    double X[Line::kVariables];
    dronePositions<Line, aurora_control::LineDrones::Vehicle>(o.X_before, X);
    if (double(o.k) * Ts < 10.0) return;
    double Q[6];
    Line::variables(X, Q);
    const double* Qd = o.layer.Qd();
    const double e[6] = {Qd[0] - Q[0], Qd[1] - Q[1], Qd[2] - Q[2], Qd[3] - Q[3], Qd[4] - Q[4], Qd[5] - Q[5]};
    const double terms[5] = {e[3] * e[3], e[4] * e[4], e[5] * e[5], e[0] * e[0] + e[1] * e[1], e[2] * e[2]};
    for (int i = 0; i < 5; ++i) sum_[i] += terms[i];
    ++n_;
  }
  double rms(int i) const { return n_ > 0 ? std::sqrt(sum_[i] / double(n_)) : 0.0; }

 private:
  double sum_[5] = {};
  long n_ = 0;
};

const char* kDroneColumns[16] = {"x", "y", "z", "phi", "theta", "psi", "dx", "dy", "dz", "dphi", "dtheta", "dpsi",
                                 "u1", "u2", "u3", "u4"};

// One row per tick k from 0: step, t, each drone's 12-state after k model
// steps and the commands it applied at tick k, then Q of those positions
// and the layer's held Qd, at round-trip precision.
class FormationCsv {
 public:
  explicit FormationCsv(const std::string& path) : f_(path.empty() ? nullptr : std::fopen(path.c_str(), "w")) {
    if (!path.empty() && !f_) throw std::runtime_error("cannot write '" + path + "'");
    if (!f_) return;
    std::fprintf(f_, "step,t");
    for (int d = 1; d <= 2; ++d) {
      for (const char* c : kDroneColumns) std::fprintf(f_, ",d%d_%s", d, c);
    }
    for (const char* prefix : {"Q", "Qd"}) {
      for (int i = 0; i < Line::kVariables; ++i) std::fprintf(f_, ",%s_%s", prefix, Line::variableName(i));
    }
    std::fprintf(f_, "\n");
  }
  ~FormationCsv() {
    if (f_) std::fclose(f_);
  }
  void add(const LineObservation& o, double Ts) {
    if (!f_) return;
    using aurora_common::writeNumber;
    std::fprintf(f_, "%ld", o.k);
    writeNumber(f_, double(o.k) * Ts);
    double P[Line::kVariables], Q[Line::kVariables];
    for (int d = 0; d < Line::kDrones; ++d) {
      for (int i = 0; i < aurora_sim::kStateSize; ++i) writeNumber(f_, o.X_before[d][i]);
      for (int i = 0; i < 4; ++i) writeNumber(f_, o.steps[d].U[i]);
    }
    dronePositions<Line, aurora_control::LineDrones::Vehicle>(o.X_before, P);
    Line::variables(P, Q);
    for (int i = 0; i < 6; ++i) writeNumber(f_, Q[i]);
    for (int i = 0; i < 6; ++i) writeNumber(f_, o.layer.Qd()[i]);
    std::fprintf(f_, "\n");
  }

 private:
  FILE* f_;
};

// The file's run with --delay's per-drone delays, checked.
LineRun loadRun(const FormationFlightOptions& o, const LineDrones::Vehicle::Params<double>& p,
                 const FormationFile& f, long ticks) {
  LineRun run = formationRun(f, p);
  const std::vector<long> delays = robotDelays(o.delays, 2, "the line", p.Ts, ticks, {0, 0}, "drone");
  for (size_t d = 0; d < o.delays.size(); ++d) {
    run.drone[d].delay = delays[d];  // replaces the file's, and its link's uplink delay (docs/links.md)
  }
  if (!o.delays.empty()) refuseFormationDelays(run, p.Ts, {"--delay (drone 1)", "--delay (drone 2)"});
  return run;
}

}  // namespace

FormationFlight flyFormationFiles(const FormationFlightOptions& o, const FormationObserver& observe) {
  return flyFormationFiles(readFormationFile(o.formation, o.config_dir), o, observe);
}

FormationFlight flyFormationFiles(const FormationFile& file, const FormationFlightOptions& o,
                                  const FormationObserver& observe) {
  // The flight's vehicle file, else the shipped one of the line's drones.
  using Vehicle = LineShapeEntry::UnnamedVehicle;
  const std::string vehicle = o.vehicle.empty() ? shippedOrPath(Vehicle::name(), o.config_dir, "vehicles") : o.vehicle;
  const auto p = aurora_sim::loadVehicleFile<Vehicle>(vehicle, "the formation's drones' laws");
  FormationFlight r{file, {}, p.Ts, 0, 0.0, {},
                    LineJudge{FormationCriteria<double>::study(), false, p.Ts, {}, {}}};
  r.ticks = formationTicks(r.file.reference.duration, p.Ts);
  r.run = loadRun(o, p, r.file, r.ticks);
  r.judge.metrics.reset();
  const long history = formationHistory(r.run);
  if (history > kMaxDelaySamples) {
    throw ConfigError("the drones' delays plus their links' jitter need " + std::to_string(history) +
                      " samples of history: accepted up to " + std::to_string(kMaxDelaySamples));
  }
  FormationErrors errors;
  const auto t0 = std::chrono::steady_clock::now();
  auto each = [&](const LineObservation& obs) {
    observe(obs, p.Ts);
    errors.add(obs, p.Ts);
    r.judge(obs);
  };
  // The full history, as the other shapes' flights (a run does not depend on it).
  r.file.drones[0].controller.withLawType([&](auto law) {
    runFormation<decltype(law), double, Line, kDelayHistory>(r.run, r.ticks, each);
  });
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (int i = 0; i < 5; ++i) r.rms[i] = errors.rms(i);
  return r;
}

void LineShapeEntry::fly(const File& file, const FormationFlightOptions& o) {
  std::unique_ptr<FormationCsv> csv;  // opened at tick 0: a refused file writes nothing
  const FormationFlight r = flyFormationFiles(file, o, [&](const LineObservation& obs, double Ts) {
    if (!csv) csv.reset(new FormationCsv(o.csv));
    csv->add(obs, Ts);
  });
  std::printf("flight: formation '%s' (line, %s, %s law on each drone), %.1f s, delays %ld and %ld samples: "
              "%ld ticks in %.3f s\n", o.formation.c_str(), formationLawName(r.file.law),
              lawNameOf(r.file.drones[0].controller), r.file.reference.duration, r.run.drone[0].delay,
              r.run.drone[1].delay, r.ticks, r.seconds);
  std::printf("  RMS formation error after 10 s: rho %.4f m, alpha %.4f rad, beta %.4f rad, position (x, y) %.4f m, "
              "height %.4f m\n", r.rms[0], r.rms[1], r.rms[2], r.rms[3], r.rms[4]);
  std::printf("%s", checksText(r.judge.criteria, r.judge.metrics, false).c_str());
}

}  // namespace aurora_control
