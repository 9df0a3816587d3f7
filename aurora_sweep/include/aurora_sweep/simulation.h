// One simulation of a sweep, from its combination index: the per-thread body
// of the CUDA kernel and the body of the scalar backend's loop (host and
// device, no allocation, no exceptions). The SIMD engine builds each lane's
// run with the same studyRun().
#pragma once

#include <type_traits>

#include "aurora_control/loop/positioning_runner.h"
#include "aurora_control/loop/predicted_loop.h"
#include "aurora_sweep/combination.h"
#include "aurora_sweep/sweep_gains.h"

namespace aurora_sweep {

// Everything a simulation needs besides its combination, in precision T,
// for vehicle `Vehicle` (aurora_sim/vehicle/).
template <class Vehicle, typename T>
struct SimSetup {
  typename Vehicle::template Params<double> vehicle;  // the vehicle file's (nominal) values
  typename Vehicle::template Params<T> model;         // the same in T: what the law inverts
  aurora_control::RunnerConfig<T> config;
  long iterations;    // loop iterations of the task (1801 for 60 s)
  bool varies_model;  // some model factor is not 1: each run scales its own vehicle
  bool ideal_link;    // every run is today's loop (SweepSpec::linkIdeal)
  // The state predictor (off: the law on the received state) and its model.
  aurora_control::PredictorForm predictor = aurora_control::PredictorForm::kOff;
  typename Vehicle::template Params<T> predictor_model;
};

static_assert(kLinkParamCount == aurora_control::kLinkValueCount, "one sweep parameter per link value");

// A combination's own run of law `Law`: its gains, its delay and its
// vehicle (the vehicle file's scaled by the combination's model factors,
// factor i being parameter kParamFirstModelFactor + i: Vehicle::scaled).
template <class Law, class Vehicle, typename T>
AURORA_HD inline aurora_control::StudyRun<typename Law::Data, T> studyRun(const SimSetup<Vehicle, T>& s,
                                                                          const Combination& c) {
  static_assert(Vehicle::kFactors <= kModelFactorCount, "the sweep holds kModelFactorCount model factors");
  aurora_control::StudyRun<typename Law::Data, T> run;
  run.model = s.model;
  run.plant = s.varies_model ? Vehicle::scaled(s.vehicle, c.v + kParamFirstModelFactor).template cast<T>()
                             : s.model;
  run.gains = SweepGains<typename Law::Data>::template from<T>(c);
  run.delay = c.delay();
  return run;
}

// Compact result (what the kernel writes back, and the chunk files hold:
// 48 bytes). The padding is a named, zeroed field, so that every byte of a
// chunk file is defined and a file is reproducible bit for bit.
struct SimResult {
  float final_pos[3];   // [m]
  int steps;            // model steps run
  double iae, itae, iasc;
  unsigned char ok;     // check i + 1 held at bit checkBit(i) (1-4 at 0-3, a formation's 5 at 5); bit 4: feasible
  unsigned char zero[3];  // always 0
  float extra;          // a formation's ground_command (FormationRecord); 0 for one robot
};
static_assert(sizeof(SimResult) == 48, "the chunk files' record: 48 bytes, no implicit padding");

// The bits of SimResult::ok, by name: check i (0-based) held, and feasible
// (checks 1-4 keep the bits they had before a formation's fifth came).
constexpr int kFeasibleBit = 4;
AURORA_HD constexpr int checkBit(int check) { return check < kFeasibleBit ? check : check + 1; }
AURORA_HD inline int checkHeld(const SimResult& r, int check) { return (r.ok >> checkBit(check)) & 1; }
AURORA_HD inline int feasible(const SimResult& r) { return (r.ok >> kFeasibleBit) & 1; }

AURORA_HD inline SimResult compactResult(const aurora_control::RunnerResult& r) {
  SimResult s;
  for (int i = 0; i < 3; ++i) s.zero[i] = 0;
  s.extra = 0.0f;
  for (int i = 0; i < 3; ++i) s.final_pos[i] = static_cast<float>(r.final_pos[i]);
  s.steps = static_cast<int>(r.steps);
  s.iae = r.iae;
  s.itae = r.itae;
  s.iasc = r.iasc;
  s.ok = 0;
  for (int i = 0; i < aurora_control::kPositioningChecks; ++i) s.ok |= static_cast<unsigned char>((r.ok[i] ? 1 : 0) << i);
  s.ok |= static_cast<unsigned char>((r.feasible ? 1 : 0) << kFeasibleBit);
  return s;
}

// The kLinkParamCount link values at `values` (LinkValue order) into l,
// a NaN one keeping l's (link.h's setLinkValue, the node's live rule).
AURORA_HD inline void applyLinkValues(aurora_control::LinkParams& l, const double* values) {
  for (int i = 0; i < kLinkParamCount; ++i) {
    if (values[i] == values[i]) aurora_control::setLinkValue(l, i, values[i]);
  }
}

// A combination's link (docs/links.md, "Links in a sweep"): `base` (the
// sweep's link, or a formation drone's) with `uplink_delay` as the uplink's
// base delay, the combination's link values (link.h's setLinkValue, the
// node's live rule; a NaN value, one a formation sweep does not give, keeps
// the base's) and, for repeat r, the seed base.seed + r.
AURORA_HD inline aurora_control::LinkParams combinationLink(const aurora_control::LinkParams& base, long uplink_delay,
                                                           const Combination& c) {
  aurora_control::LinkParams l = base;
  l.uplink.delay = uplink_delay;
  applyLinkValues(l, c.v + kParamFirstLinkValue);
  l.seed = base.seed + static_cast<uint32_t>(c.repeat());
  return l;
}

// A combination's run over an ideal link: today's loop, the delay rule.
template <class Law, typename T, int Capacity, class Setup>
AURORA_HD inline aurora_control::RunnerResult runCombination(const Setup& setup, const Combination&,
                                                             const aurora_control::StudyRun<typename Law::Data, T>& run,
                                                             std::false_type /*linked*/) {
  aurora_control::NoObserver none;
  return aurora_control::runClosedLoop<Law, T, Capacity>(run, setup.config, setup.iterations, none);
}

// Over its link's model, whose draws are keyed by the combination (not its
// repeat, not the chunk), so every backend and range split draws the same.
// The channels and the commands in flight live in this frame
// (Capacity-sized, as the history): no allocation, host and device.
template <class Law, typename T, int Capacity, class Setup>
AURORA_HD inline aurora_control::RunnerResult runCombination(const Setup& setup, const Combination& c,
                                                             const aurora_control::StudyRun<typename Law::Data, T>& run,
                                                             std::true_type /*linked*/) {
  aurora_control::NoObserver none;
  aurora_control::ModelLink<Capacity, T, Law::Vehicle::kInputs> link(
      combinationLink(setup.config.link, run.delay, c), run.delay, static_cast<uint64_t>(c.key), double(run.plant.Ts));
  return aurora_control::runClosedLoopOver<Law, T, Capacity>(run, setup.config, setup.iterations, none, link);
}

// The run with the state predictor (docs/predictor.md, "In a sweep"): its
// rings in this frame (twice the history: the delay and the command delay
// fit), its command delay the combination's downlink base delay; the study
// clamps nowhere, so neither does its model of the vehicle.
template <class Law, typename T, int Capacity, class Setup, class Link>
AURORA_HD inline aurora_control::RunnerResult runPredicted(const Setup& setup,
                                                           const aurora_control::StudyRun<typename Law::Data, T>& run,
                                                           long command_delay, Link& link) {
  aurora_control::NoObserver none;
  const aurora_control::CommandPath path{command_delay, 0, setup.config.clamp_at_drone};
  aurora_control::StatePredictor<typename Law::Vehicle, T, 2 * Capacity> predictor(setup.predictor,
                                                                                  setup.predictor_model, path);
  return aurora_control::runPredictedOver<Law, T, Capacity>(run, setup.config, setup.iterations, none, predictor,
                                                            link);
}
template <class Law, typename T, int Capacity, class Setup>
AURORA_HD inline aurora_control::RunnerResult runPredictedCombination(
    const Setup& setup, const Combination&, const aurora_control::StudyRun<typename Law::Data, T>& run,
    std::false_type /*linked*/) {
  aurora_control::IdealLink link{run.delay};
  return runPredicted<Law, T, Capacity>(setup, run, 0, link);
}
template <class Law, typename T, int Capacity, class Setup>
AURORA_HD inline aurora_control::RunnerResult runPredictedCombination(
    const Setup& setup, const Combination& c, const aurora_control::StudyRun<typename Law::Data, T>& run,
    std::true_type /*linked*/) {
  const aurora_control::LinkParams l = combinationLink(setup.config.link, run.delay, c);
  aurora_control::ModelLink<Capacity, T, Law::Vehicle::kInputs> link(l, run.delay, static_cast<uint64_t>(c.key),
                                                                     double(run.plant.Ts));
  return runPredicted<Law, T, Capacity>(setup, run, l.downlink.delay, link);
}

// Combination `index`'s run of law `Law` (over its link when `Linked`, with
// the predictor when `Predicted`): the CUDA thread's and the scalar loop's
// body.
// (Without the predictor its code is not instantiated at all: the kernels'
// registers stay those of the loop without it.)
template <class Law, typename T, int Capacity, bool Linked, class Setup>
AURORA_HD inline aurora_control::RunnerResult runCombinationOf(const Setup& setup, const Combination& c,
                                                               std::false_type /*predicted*/) {
  return runCombination<Law, T, Capacity>(setup, c, studyRun<Law>(setup, c), std::integral_constant<bool, Linked>());
}
template <class Law, typename T, int Capacity, bool Linked, class Setup>
AURORA_HD inline aurora_control::RunnerResult runCombinationOf(const Setup& setup, const Combination& c,
                                                               std::true_type /*predicted*/) {
  return runPredictedCombination<Law, T, Capacity>(setup, c, studyRun<Law>(setup, c),
                                                   std::integral_constant<bool, Linked>());
}
template <class Law, typename T, int Capacity, bool Linked = false, bool Predicted = false>
AURORA_HD inline SimResult simulateCombination(const SimSetup<typename Law::Vehicle, T>& setup, const GridView& grid,
                                               long index) {
  const Combination c = grid.decode(index);
  return compactResult(
      runCombinationOf<Law, T, Capacity, Linked>(setup, c, std::integral_constant<bool, Predicted>()));
}

}  // namespace aurora_sweep
