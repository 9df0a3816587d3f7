// Loading and validating a sweep file (YAML). Every problem is reported
// before any simulation runs, naming the key and what is accepted.
#pragma once

#include <stdexcept>
#include <string>

#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

struct SweepFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads `path`. Relative file names inside (vehicle, points) resolve against
// the sweep file's folder first, then `config_dir` (the shipped config/).
SweepSpec loadSweepFile(const std::string& path, const std::string& config_dir);

// Reads the vehicle file's keys (vehicle_keys.h), strictly.
aurora_sim::ArdroneParams<double> loadVehicleFile(const std::string& path);

}  // namespace aurora_sweep
