// A sweep: which simulations to run and how to judge them. Loaded from a
// sweep file (sweep_file.h), validated before any work.
#pragma once

#include <string>
#include <vector>

#include "aurora_control/feasibility.h"
#include "aurora_sim/ardrone_params.h"
#include "aurora_sweep/combination.h"

namespace aurora_sweep {

enum class Precision { kDouble, kFloat };

inline const char* precisionName(Precision p) { return p == Precision::kDouble ? "double" : "float"; }

struct Axis {
  ParamId param;
  std::vector<double> values;
};

struct SweepSpec {
  std::string file;                 // the sweep file it came from
  std::string name;
  std::string controller = "pd_saturated";
  std::string vehicle_file;
  aurora_sim::ArdroneParams<double> vehicle{};
  double desired[3] = {2.0, 1.0, 2.0};  // positioning target [m]
  double duration = 60.0;               // [s]
  aurora_control::FeasibilityCriteria<double> criteria =
      aurora_control::FeasibilityCriteria<double>::study();
  std::vector<Axis> axes;           // in variation order: axes[0] varies fastest
  double fixed[kParamCount] = {0.0, 0.0, 0.0};
  std::vector<double> points;       // (kp, kd, delay) triples, when read from a CSV
  std::string points_file;
  bool early_stop = true;
  bool clamp_commands = false;
  Precision precision = Precision::kDouble;
  long max_delay = 0;               // largest delay of any combination [samples]
  // How the points were made: grid (axes or a points file) or a sampling
  // design (design.h) of `samples` points from `seed`, stored in `points`.
  std::string design = "grid";
  long samples = 0;
  unsigned long long seed = 0;

  // A view for decoding indices; valid while this spec lives and is unchanged.
  GridView view() const {
    GridView g{};
    g.n_axes = static_cast<int>(axes.size());
    for (int a = 0; a < g.n_axes; ++a) {
      g.param[a] = axes[a].param;
      g.count[a] = static_cast<long>(axes[a].values.size());
      g.values[a] = axes[a].values.data();
    }
    for (int i = 0; i < kParamCount; ++i) g.fixed[i] = fixed[i];
    g.points = points.empty() ? nullptr : points.data();
    g.n_points = static_cast<long>(points.size() / 3);
    return g;
  }
  long size() const { return view().size(); }

  // The part of the index space a backend computes, [range_begin, range_end):
  // one chunk of a resumable or MPI run (chunk_store.h); range_end < 0: to
  // the end. A backend's output holds rangeSize() results, result i being
  // combination rangeBegin() + i.
  long range_begin = 0;
  long range_end = -1;
  long rangeBegin() const { return range_begin; }
  long rangeEnd() const { return range_end < 0 ? size() : range_end; }
  long rangeSize() const { return rangeEnd() - rangeBegin(); }
};

inline const char* paramName(int id) {
  switch (id) {
    case kParamKp: return "kp";
    case kParamKd: return "kd";
    default: return "delay";
  }
}

}  // namespace aurora_sweep
