// flight --formation: a formation file flown offline (formation_runner.h),
// its formation errors printed, its trajectory written as CSV. The same
// flight from Python: aurora._core's simulate_formation_files.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/formation_yaml.h"

namespace aurora_control {

struct FormationFlightOptions {
  std::string formation, vehicle, csv, config_dir;
  std::vector<long> delays;  // per drone, replacing the file's (empty: the file's)
  std::string law;           // a triangle's law instead of the file's (flight --law; empty: the file's)
};

// --delay's per-robot delays [samples of Ts] for a formation of `robots`
// (none given: `none`), each in the delay rule's range and shorter than the
// run's `ticks`; refused naming the `robot` ("drone", "robot") by its number
// and `shape` ("the line", ...).
std::vector<long> robotDelays(const std::vector<long>& given, size_t robots, const std::string& shape, double Ts,
                              long ticks, const std::vector<long>& none, const std::string& robot = "robot");

// Each tick, with the drones' sample time Ts [s].
using FormationObserver = std::function<void(const FormationObservation<double, LineFormation<double>>&, double Ts)>;

// What a formation flight gives besides its ticks.
struct FormationFlight {
  FormationFile file;
  FormationRun<double, LineFormation<double>> run;  // with the delays in force
  double Ts = 0.0;
  long ticks = 0;
  double seconds = 0.0;  // wall time of the run
  // RMS after 10 s (docs/formation.md, "Formation errors"): rho [m], alpha,
  // beta [rad], the formation's horizontal position and height [m].
  double rms[5] = {};
  FormationJudge<double> judge;  // the formation checks, as a sweep judges them
};

// Loads the files (refusals as ConfigError naming the key) and flies every
// tick through `observe`.
FormationFlight flyFormationFiles(const FormationFlightOptions& o, const FormationObserver& observe);

// The tool: the flight, its CSV (o.csv) and its printed errors and checks.
void flyFormation(const FormationFlightOptions& o);

// Flies steps k = 0 .. steps - 1 (fly(k)) and writes each one's row to the
// CSV at `path` (row(file, k); none when path is empty) under `header`;
// returns the wall time of the flight [s]. AuRoRA's formations' tools.
template <class Fly, class Row>
double flyWithCsv(const std::string& path, const std::string& header, long steps, Fly&& fly, Row&& row) {
  FILE* csv = path.empty() ? nullptr : std::fopen(path.c_str(), "w");
  if (!path.empty() && !csv) throw std::runtime_error("cannot write '" + path + "'");
  if (csv) std::fprintf(csv, "%s", header.c_str());
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < steps; ++k) {
    fly(k);
    if (csv) row(csv, k);
  }
  if (csv) std::fclose(csv);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The same for a UAV-UGV line file (shape: uav_ugv_line; uav_ugv_yaml.h)
// and for a triangle file (shape: triangle; triangle_yaml.h).
void flyUavUgvLine(const FormationFlightOptions& o);
void flyTriangle(const FormationFlightOptions& o);

}  // namespace aurora_control
