// A sweep: which simulations to run and how to judge them. Loaded from a
// sweep file (sweep_file.h), validated before any work.
#pragma once

#include <string>
#include <vector>

#include "aurora_control/loop/feasibility.h"
#include "aurora_control/formation/formation_checks.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_control/formation/shapes.h"
#include "aurora_control/link/link.h"
#include "aurora_control/predictor/state_predictor.h"
#include "aurora_control/task/task.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "aurora_sweep/combination.h"
#include "aurora_sweep/parameters.h"

namespace aurora_sweep {

enum class Precision { kDouble, kFloat };

// The most runs of one combination (sweep.repeats).
constexpr long kMaxRepeats = 100000;

inline const char* precisionName(Precision p) { return p == Precision::kDouble ? "double" : "float"; }

struct Axis {
  ParamId param;
  std::vector<double> values;
};

template <class ShapeEntry>
using SweepRunOf = typename ShapeEntry::SweepRun;

struct SweepSpec {
  std::string file;                 // the sweep file it came from
  std::string name;
  std::string controller = "pd_saturated";  // the law's name (a formation's: its robots', its entry's sweepFacts)
  // The vehicle the controller flies (its file: `vehicle:`, of that
  // `type:`): its parameters in its type's place of `vehicles`
  // (paramsOf); the AR.Drone's are a formation sweep's drones' too.
  std::string vehicle_file;
  std::string vehicle_type = aurora_sim::DefaultVehicle::name();
  aurora_sim::VehicleParamsSet vehicles{};
  template <class Vehicle>
  const typename Vehicle::template Params<double>& paramsOf(Vehicle) const {
    return vehicles.template of<Vehicle>();
  }
  template <class Vehicle>
  typename Vehicle::template Params<double>& paramsOf(Vehicle) {
    return vehicles.template of<Vehicle>();
  }
  // The default vehicle's (vehicle_type.h): a sweep's that names none.
  const aurora_sim::DefaultVehicle::Params<double>& defaultVehicle() const {
    return paramsOf(aurora_sim::DefaultVehicle());
  }
  double Ts() const {
    double Ts = defaultVehicle().Ts;
    vehicles.withType(vehicle_type, [&](const auto& p) { Ts = p.Ts; });
    return Ts;
  }
  // The state predictor (sweep file 'predictor:', docs/predictor.md,
  // "In a sweep"): its form and its model's vehicle file (the sweep's
  // vehicle file by default: the plant's model factors leave it nominal).
  aurora_control::PredictorForm predictor = aurora_control::PredictorForm::kOff;
  std::string predictor_model_file;
  bool predicting() const { return predictor != aurora_control::PredictorForm::kOff; }
  // The task (one schema with the node: positioning point, waypoints,
  // circle, lemniscate); the study's by default.
  aurora_control::Task<double> task = aurora_control::positioningTask(2.0, 1.0, 2.0, 60.0);
  double duration() const { return formation() ? formation_duration : task.duration(); }
  // A formation sweep (sweep file 'formation:', docs/formation.md,
  // "Formation sweeps"): the formation file's run is every combination's,
  // with its robots' delays (delay_1, ...), the formation's gains (a
  // triangle's law) and the link values the sweep gives; judged by the
  // formation's checks. Its shape's run: its entry's (the two-drone
  // line's, `law` its drones'; the UAV-UGV line's; the triangle's, three
  // AR.Drones on the underactuated law).
  std::string formation_file;
  SweepShape shape = SweepShape::kNone;
  // Each shape's run (its entry's SweepRun), the sweep's shape's read from
  // its file: run<Entry>().
  typename aurora_control::PerShape<SweepRunOf, aurora_control::KnownShapes>::type runs;
  template <class Entry>
  const typename Entry::SweepRun& run() const {
    return std::get<aurora_control::shapeIndex<Entry>()>(runs);
  }
  template <class Entry>
  typename Entry::SweepRun& run() {
    return std::get<aurora_control::shapeIndex<Entry>()>(runs);
  }
  double formation_duration = 0.0;  // [s] its flights'
  aurora_control::FormationCriteria<double> formation_criteria =
      aurora_control::FormationCriteria<double>::study();
  bool formation() const { return shape != SweepShape::kNone; }
  // Whether a formation's robots fly a predictor (their controller files').
  bool formationPredicting() const {
    bool on = false;
    if (formation()) withFormation([&](const auto& run, auto) { on = aurora_control::anyPredictor(run); });
    return on;
  }
  // f(run, law) with the formation's run and its robots' law type (a
  // default value: its entry's withRobotLaw); the one place a formation
  // sweep's types are chosen. (A single-robot sweep's: the first shape's,
  // never flown.)
  template <class F>
  void withFormation(F&& f) const {
    if (!formation()) return withFormationOf(aurora_common::FirstType<aurora_control::KnownShapes>::type(), f);
    withSweepShape(shape, [&](auto e) { withFormationOf(e, f); });
  }
  template <class Entry, class F>
  void withFormationOf(Entry, F&& f) const {
    Entry::withRobotLaw(controller, [&](auto l) { f(run<Entry>(), l); });
  }
  // Where its parameters sit (combination.h): its entry's ParamShape's
  // (a single-robot sweep's: the line's).
  ShapeLayout layout() const {
    ShapeLayout at = kLineLayout;
    withSweepShape(shape, [&](auto e) { at = shapeLayout<typename decltype(e)::ParamShape>(); });
    return at;
  }
  // Whether its shape has laws a sweep varies (formation_law: the triangle's).
  bool variesFormationLaw() const {
    bool varies = false;
    withSweepShape(shape, [&](auto e) { varies = decltype(e)::kSweepLaws > 0; });
    return varies;
  }
  // Its robots' step [s] (every robot's: the files make them one).
  double formationTs() const {
    double Ts = 0.0;
    withFormation([&](const auto& run, auto) { Ts = double(run.drone[0].plant.Ts); });
    return Ts;
  }
  // Robot d's own link (its formation file's).
  aurora_control::LinkParams robotLink(int d) const {
    aurora_control::LinkParams l;
    withFormation([&](const auto& run, auto) { l = run.drone[d].link; });
    return l;
  }
  // The loop iterations (ticks) of every run: 1801 for the 60 s study.
  long iterations() const {
    return formation() ? aurora_control::formationTicks(duration(), formationTs())
                       : aurora_control::studyIterationCount(duration(), Ts());
  }
  // A formation sweep's robots' own law's gains (robot_gains.h): the rows
  // of robotGainParam(0, 0) on, named by each robot's law (k1_x_2, kc1_1);
  // a robot's room its law does not use has no name. Set with the
  // formation (readSweepFormation).
  std::vector<ParamInfo> robot_gains;
  // Parameter id's name and rules in this sweep (its shape's, its robots',
  // its vehicle's model factors).
  const ParamInfo& param(int id) const {
    const int row = id - kParamFirstRobotGain, factor = id - kParamFirstModelFactor;
    if (row >= 0 && row < static_cast<int>(robot_gains.size())) return robot_gains[static_cast<size_t>(row)];
    if (!formation() && factor >= 0 && factor < kModelFactorCount) return modelFactorInfo(vehicle_type, factor);
    return paramInfo(id, shape);
  }
  const char* paramNameOf(int id) const { return param(id).name.c_str(); }
  // Whether this sweep accepts parameter `id` (parameters.h).
  bool accepts(int id) const { return paramApplies(param(id), controller, shape); }
  // The parameter a sweep file names `name` (-1: none of this sweep's).
  int paramId(const std::string& name) const {
    for (int id = 0; id < kParamCount && !name.empty(); ++id) {
      if (param(id).name == name) return id;
    }
    return -1;
  }
  // The names it accepts, in ParamId order, comma separated.
  std::string acceptedNames() const {
    std::string names;
    for (int id = 0; id < kParamCount; ++id) {
      if (accepts(id)) names += (names.empty() ? "" : ", ") + param(id).name;
    }
    return names;
  }
  aurora_control::FeasibilityCriteria<double> criteria =
      aurora_control::FeasibilityCriteria<double>::study();
  std::vector<Axis> axes;           // in variation order: axes[0] varies fastest
  double fixed[kParamCount];        // parameters not varied (parameters.h defaults)
  std::vector<double> points;       // rows of the point_params' values (CSV file or design)
  std::vector<int> point_params;    // ParamId of each column of `points`
  std::string points_file;
  bool early_stop = true;
  bool clamp_commands = false;
  Precision precision = Precision::kDouble;
  long max_delay = 0;               // largest delay of any combination [samples]
  // The link (sweep file 'link:', docs/links.md), ideal by default; set it
  // with setLink. Each combination's delay is its uplink's base delay, its
  // link values (uplink_jitter ... downlink_burst: fixed[] or varied)
  // replace the link's, and its repeat r draws with seed link.seed + r
  // (combinationLink, simulation.h). After loading, `link` holds the fixed
  // values too.
  aurora_control::LinkParams link;
  std::string link_file;
  long repeats = 1;  // runs of each combination, each with its own link seed
  // The history the runs need: the largest delay plus jitter on either
  // direction over every combination.
  long historyNeeded() const {
    if (formation()) return formationHistoryNeeded();
    aurora_control::LinkParams worst = link;
    for (int i : {aurora_control::kLinkUplinkJitter, aurora_control::kLinkDownlinkDelay,
                  aurora_control::kLinkDownlinkJitter}) {
      aurora_control::setLinkValue(worst, i, maxValue(kParamFirstLinkValue + i));
    }
    return worst.historyNeeded(max_delay);
  }
  // A formation drone's link with the sweep's largest value of each link
  // value it gives that drone (the drone's own for the others).
  aurora_control::LinkParams formationWorstLink(int d) const {
    aurora_control::LinkParams worst = robotLink(d);
    for (int i = 0; i < kLinkParamCount; ++i) {
      if (droneLinkValueGiven(d, i)) aurora_control::setLinkValue(worst, i, maxValue(droneLinkParam(d, i)));
    }
    return worst;
  }
  // A formation's: the largest over its drones of the drone's largest delay
  // plus its worst link's jitter.
  long formationHistoryNeeded() const {
    long longest = 0;
    for (int d = 0; d < layout().robots; ++d) {
      const long h = formationWorstLink(d).historyNeeded(static_cast<long>(maxValue(layout().delay(d))));
      longest = h > longest ? h : longest;
    }
    return longest;
  }
  // Whether the sweep gives link value i (fixed or varied); a formation
  // sweep's drones otherwise keep their own (the fixed value is NaN).
  bool linkValueGiven(int i) const { return given(kParamFirstLinkValue + i); }
  // The parameter that gives formation drone d its link value i: its own
  // (uplink_loss_2) when the sweep gives it, else the drones' common one
  // (formationCombination applies them in that order).
  int droneLinkParam(int d, int i) const {
    const int own = layout().linkValue(d, i);
    return given(own) ? own : kParamFirstLinkValue + i;
  }
  bool droneLinkValueGiven(int d, int i) const { return given(droneLinkParam(d, i)); }
  // Fixed to a number or varied (a NaN fixed value is "not given").
  bool given(int id) const { return varies(id) || !(fixed[id] != fixed[id]); }
  // The link for every combination and the fixed link values, from a link
  // file (the values a sweep file gives or varies replace them).
  void setLink(const aurora_control::LinkParams& l) {
    link = l;
    for (int i = 0; i < kLinkParamCount; ++i) fixed[kParamFirstLinkValue + i] = aurora_control::linkValueOf(l, i);
  }
  // Every combination runs today's loop: an ideal link, no link value varies.
  bool linkIdeal() const {
    for (int i = 0; i < kLinkParamCount; ++i) {
      if (varies(kParamFirstLinkValue + i)) return false;
    }
    if (!formation()) return link.ideal();
    for (int d = 0; d < layout().robots; ++d) {
      aurora_control::LinkParams l = robotLink(d);
      for (int i = 0; i < kLinkParamCount; ++i) {
        if (varies(droneLinkParam(d, i))) return false;
        if (droneLinkValueGiven(d, i)) aurora_control::setLinkValue(l, i, fixed[droneLinkParam(d, i)]);
      }
      if (!l.ideal()) return false;
    }
    return true;
  }
  // f(v) for every value parameter `id` takes: fixed, on an axis or in the
  // points (once per row).
  template <class F>
  void forEachValue(int id, F&& f) const {
    if (!varies(id)) f(fixed[id]);
    for (const Axis& a : axes) {
      for (double v : a.values) {
        if (a.param == id) f(v);
      }
    }
    const size_t cols = point_params.size();
    for (size_t j = 0; j < cols; ++j) {
      for (size_t i = j; point_params[j] == id && i < points.size(); i += cols) f(points[i]);
    }
  }
  double maxValue(int id) const {
    double hi = -1e300;
    forEachValue(id, [&](double v) { hi = v > hi ? v : hi; });
    return hi;
  }

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
    g.points_first = 0;
    g.point_cols = static_cast<int>(point_params.size());
    for (int j = 0; j < g.point_cols; ++j) g.point_param[j] = point_params[j];
    g.n_points = g.point_cols > 0 ? static_cast<long>(points.size()) / g.point_cols : 0;
    g.repeats = repeats;
    return g;
  }

  SweepSpec() {
    for (int id = 0; id < kParamCount; ++id) fixed[id] = paramDefault(id, shape);
  }

  // Whether a parameter varies (on an axis or a points column; the repeat
  // with repeats).
  bool varies(int id) const {
    if (id == kParamRepeat) return repeats > 1;
    for (const Axis& a : axes) {
      if (a.param == id) return true;
    }
    for (int p : point_params) {
      if (p == id) return true;
    }
    return false;
  }

  // Some model factor varies or is not 1: each run scales its own drone.
  bool variesModel() const {
    for (int i = 0; i < kModelFactorCount; ++i) {
      const int id = kParamFirstModelFactor + i;
      if (varies(id) || fixed[id] != 1.0) return true;
    }
    return false;
  }

  // The parameters of each result row: the law's gains, the delay, the
  // model factors that vary or are not 1, the link's values when the link is
  // not ideal, the repeat when there are repeats; a formation's: its drones'
  // delays, the formation gains it varies, the link values and the robots'
  // gains it gives (ParamId order).
  std::vector<int> columns() const {
    std::vector<int> c;
    for (int id = 0; id < kParamCount; ++id) {
      const ParamGroup group = param(id).group;
      const bool shown = group == ParamGroup::kModelFactor ? varies(id) || fixed[id] != 1.0
                         : group == ParamGroup::kLink   ? !linkIdeal() && (!formation() || linkValueGiven(id - kParamFirstLinkValue))
                         : group == ParamGroup::kRepeat ? repeats > 1
                         : group == ParamGroup::kFormationGain ? varies(id)
                         : group == ParamGroup::kFormationLaw ? formation() && accepts(id)
                         : group == ParamGroup::kDroneLink || group == ParamGroup::kRobotGain ? formation() && given(id)
                                                        : accepts(id);
      if (shown) c.push_back(id);
    }
    return c;
  }
  long size() const { return view().size(); }
  // Distinct combinations (each run `repeats` times).
  long combinations() const { return view().combinations(); }

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

}  // namespace aurora_sweep
