// flight --formation: a formation file flown offline (formation_runner.h),
// its formation errors printed, its trajectory written as CSV.
#pragma once

#include <string>
#include <vector>

namespace aurora_control {

struct FormationFlightOptions {
  std::string formation, vehicle, csv, config_dir;
  std::vector<long> delays;  // per drone, replacing the file's (empty: the file's)
};

void flyFormation(const FormationFlightOptions& o);

}  // namespace aurora_control
