#include "sweep_file_formation.h"

#include <limits>
#include <stdexcept>

#include "aurora_control/formation/shapes.h"
#include "aurora_sweep/robot_gains.h"

namespace aurora_sweep {

namespace {

// A sweep's robots are simulated: the latency a predictor's horizon stands
// for on a real robot is their links' (docs/predictor.md); their predictors'
// rings are twice the sweep's history, which a horizon would pass.
void refusePredictorHorizon(const aurora_control::YamlReader& r, const SweepSpec& spec) {
  spec.withFormation([&](const auto& run, auto) {
    for (int d = 0; d < spec.layout().robots; ++d) {
      if (!run.drone[d].predictor.on() || run.drone[d].predictor.path.horizon == 0) continue;
      r.fail("sweep.formation", "= '" + spec.formation_file + "': robot " + std::to_string(d + 1) +
                                    "'s controller file gives 'predictor.horizon' (" +
                                    std::to_string(run.drone[d].predictor.path.horizon) +
                                    " samples), refused in a sweep: its simulated robots' latency is their links' "
                                    "(give it as a link's downlink delay); accepted 'predictor.horizon: 0'");
    }
  });
}

// Each robot's own law's gains (robot_gains.h), named with its number
// (k1_x_2); their values NaN: each robot keeps its file's gains unless the
// sweep gives one.
void nameRobotGains(SweepSpec& spec) {
  spec.robot_gains.assign(kParamRobotGainEnd - kParamFirstRobotGain, ParamInfo{"", ParamGroup::kUnused, 0.0, 0.0, "", false});
  spec.withFormation([&](const auto& run, auto law) {
    using Gains = RobotGains<decltype(law)>;
    for (int d = 0; d < spec.layout().robots; ++d) {
      const std::vector<LawGainRow> rows = Gains::rows(run.drone[d].plant);
      if (rows.size() > static_cast<size_t>(kRobotGainRoom)) throw std::logic_error("a law with more gains than a robot's room");
      const std::string robot = std::to_string(d + 1), law_name = Gains::law(run.drone[d].plant);
      for (size_t i = 0; i < rows.size(); ++i) {
        spec.robot_gains[static_cast<size_t>(robotGainParam(d, int(i)) - kParamFirstRobotGain)] =
            ParamInfo{rows[i].name + ("_" + robot), ParamGroup::kRobotGain, rows[i].min, rows[i].max,
                      "robot " + robot + "'s " + law_name + " law's gain range", rows[i].whole, law_name};
      }
    }
  });
}

}  // namespace

void readSweepFormation(const aurora_control::YamlReader& r, const YAML::Node& sweep, const std::string& file,
                        const std::string& config_dir, SweepSpec& spec) {
  for (const char* key : {"controller", "task", "link", "clamp_commands"}) {
    if (sweep[key]) {
      r.fail(std::string("sweep.") + key, "is refused in a formation sweep: the formation file '" + file +
                                              "' gives it (per drone; docs/formation.md, \"Formation sweeps\")");
    }
  }
  // The shape's file as the sweep flies it: its entry's run (SweepSpec::run)
  // and what the sweep's records name (shapes.h's entries, sweepFacts).
  aurora_control::withFormationFile(file, config_dir, "", [&](auto entry, const auto& shape_file) {
    using Entry = decltype(entry);
    const aurora_control::ShapeSweepFacts facts = Entry::sweepFacts(shape_file);
    if (!facts.refusal.empty()) r.fail("sweep.formation", "= '" + file + "' " + facts.refusal);
    spec.shape = sweepShapeOf<Entry>();
    spec.run<Entry>() = Entry::sweepRun(shape_file, spec.vehicles);
    spec.formation_duration = facts.duration;
    spec.controller = facts.controller;
  });
  spec.formation_file = file;
  refusePredictorHorizon(r, spec);
  nameRobotGains(spec);
  // The shape's room: its defaults, then the file's delays, gains and law;
  // the link values NaN (each robot keeps its own link unless the sweep
  // gives one).
  for (int id = kParamFirstRobotParam; id < kParamCount; ++id) spec.fixed[id] = paramDefault(id, spec.shape);
  const ShapeLayout at = spec.layout();
  spec.withFormation([&](const auto& run, auto) {
    for (int d = 0; d < at.robots; ++d) spec.fixed[at.delay(d)] = double(run.drone[d].delay);
    for (int i = 0; i < at.variables; ++i) spec.fixed[at.k1(i)] = double(run.gains.k1[i]), spec.fixed[at.k2(i)] = double(run.gains.k2[i]);
    if (spec.variesFormationLaw()) spec.fixed[kParamFormationLaw] = double(static_cast<int>(run.law));
  });
  for (int i = 0; i < kLinkParamCount; ++i) spec.fixed[kParamFirstLinkValue + i] = std::numeric_limits<double>::quiet_NaN();
}

void readFormationCriteria(const aurora_control::YamlReader& r, const YAML::Node& c,
                           aurora_control::FormationCriteria<double>& cr) {
  constexpr int kKeys = 8;
  const char* names[kKeys] = {"settle_time",   "max_position_error", "max_shape_error",  "max_iae_position",
                              "max_iae_shape", "min_distance",       "max_ground_speed", "max_ground_turn_rate"};
  double* into[kKeys] = {&cr.settle_time,   &cr.max_position_error, &cr.max_shape_error,  &cr.max_iae_position,
                         &cr.max_iae_shape, &cr.min_distance,       &cr.max_ground_speed, &cr.max_ground_turn_rate};
  const char* units[kKeys] = {"s", "m", "m", "m s", "m s", "m", "m/s", "rad/s"};
  r.onlyKeys(c, "sweep.criteria", {names, names + kKeys});
  for (int i = 0; i < kKeys; ++i) {
    const std::string key = std::string("sweep.criteria.") + names[i];
    // The settle time and the distance may be 0 (judge from the start; no collision check).
    if (c[names[i]]) *into[i] = r.numberIn(c[names[i]], key, 0.0, 1e9, units[i], i == 0 || i == 5);
  }
}

namespace {

// The smallest burst above 1 drone d's direction runs with (its own when
// the sweep gives none).
double smallestBurst(const SweepSpec& spec, int d, int burst_value, double own) {
  if (!spec.droneLinkValueGiven(d, burst_value)) return own;
  double smallest = 1e300;
  spec.forEachValue(spec.droneLinkParam(d, burst_value), [&](double b) { smallest = b > 1.0 && b < smallest ? b : smallest; });
  return smallest;
}

}  // namespace

void checkFormationLinks(const aurora_control::YamlReader& r, const SweepSpec& spec) {
  bool draws = false;
  for (int d = 0; d < spec.layout().robots; ++d) {
    const aurora_control::LinkParams worst = spec.formationWorstLink(d);
    const aurora_control::LinkDirection* dirs[2] = {&worst.uplink, &worst.downlink};
    const int bursts[2] = {aurora_control::kLinkUplinkBurst, aurora_control::kLinkDownlinkBurst};
    for (int j = 0; j < 2; ++j) {
      aurora_control::LinkDirection dir = *dirs[j];
      dir.burst = smallestBurst(spec, d, bursts[j], dir.burst);
      const std::string refusal = aurora_control::burstLossRefusal(dir);
      if (dir.burst < 1e300 && !refusal.empty()) {
        r.fail(std::string("sweep.parameters.") + spec.paramNameOf(spec.droneLinkParam(d, bursts[j] - 1)),
               "= " + aurora_control::YamlReader::fmt(dir.loss) + " (its largest, on drone " + std::to_string(d + 1) +
                   "'s link) " + refusal);
      }
      draws = draws || dir.loss > 0.0 || dir.jitter_max > 0.0;
    }
  }
  if (spec.historyNeeded() > aurora_control::kMaxDelaySamples) {
    r.fail("sweep.parameters", "needs " + std::to_string(spec.historyNeeded()) + " samples of history (a drone's " +
                                   "largest delay plus its link's jitter): accepted up to " +
                                   std::to_string(aurora_control::kMaxDelaySamples));
  }
  if (spec.repeats > 1 && !draws) {
    r.fail("sweep.repeats", "= " + std::to_string(spec.repeats) + " draws nothing: no drone's link has jitter or "
           "loss, so every repeat is the same run; give the drones' links jitter or loss (the formation file's "
           "links or the link parameters), or remove repeats");
  }
}

}  // namespace aurora_sweep
