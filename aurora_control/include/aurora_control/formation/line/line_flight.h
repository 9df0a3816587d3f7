// The two-drone line's flight (flight --formation with a line's file, and
// aurora._core's simulate_formation_files): its run with the delays in
// force, every tick observed, its formation errors and checks.
#pragma once

#include <functional>

#include "aurora_control/formation/formation_flight.h"
#include "aurora_control/formation/line/line_yaml.h"

namespace aurora_control {

// Each tick, with the drones' sample time Ts [s].
using FormationObserver = std::function<void(const LineObservation&, double Ts)>;

// What a formation flight gives besides its ticks.
struct FormationFlight {
  FormationFile file;
  LineRun run;  // with the delays in force
  double Ts = 0.0;
  long ticks = 0;
  double seconds = 0.0;  // wall time of the run
  // RMS after 10 s (docs/formation.md, "Formation errors"): rho [m], alpha,
  // beta [rad], the formation's horizontal position and height [m].
  double rms[5] = {};
  LineJudge judge;  // the formation checks, as a sweep judges them
};

// Flies the line's `file` with the options' vehicle file and delays
// (refusals as ConfigError naming the key), every tick through `observe`;
// the second form reads o.formation first. The tool's form
// (LineShapeEntry::fly) writes its CSV (o.csv) and prints its errors and
// checks.
FormationFlight flyFormationFiles(const FormationFile& file, const FormationFlightOptions& o,
                                  const FormationObserver& observe);
FormationFlight flyFormationFiles(const FormationFlightOptions& o, const FormationObserver& observe);

}  // namespace aurora_control
