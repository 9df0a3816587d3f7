// Loading and validating a sweep file (YAML). Every problem is reported
// before any simulation runs, naming the key and what is accepted.
#pragma once

#include <stdexcept>
#include <string>

#include "aurora_control/params/yaml_reader.h"
#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

// The shared configuration error (aurora_control/params/yaml_reader.h): the sweep
// file, the task and controller schemas are read with the same rules.
using aurora_control::ConfigError;

// Reads `path`. Relative file names inside (vehicle, points) resolve against
// the sweep file's folder first, then `config_dir` (the shipped config/).
SweepSpec loadSweepFile(const std::string& path, const std::string& config_dir);

}  // namespace aurora_sweep
