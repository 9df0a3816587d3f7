// The thesis's study of the AR.Drone 2.0 (docs/delay-and-study.md): its
// runs of either of its laws, chosen at run time, on the offline runner
// (positioning_runner.h), and what an observer of its flight sees: the
// AR.Drone's own, beside its law (law/ardrone2). The self-check and the
// study's tests call these.
#pragma once

#include "aurora_control/law/ardrone2/control_law.h"
#include "aurora_control/loop/positioning_runner.h"

namespace aurora_control {

// An AR.Drone run of either law (flight_runner.h, the study's runs), and
// what an observer of a flight sees.
template <typename T>
using ArdroneRun = StudyRun<ArdroneLawData, T>;
using FlightObservation = LoopObservation<aurora_sim::Ardrone2, double>;

// The same with the AR.Drone's law chosen at run time.
template <typename T, typename Observer = NoObserver>
RunnerResult runLoop(LawType law, const ArdroneRun<T>& run, const RunnerConfig<T>& cfg, long iterations,
                     Observer observe = Observer()) {
  RunnerResult result;
  withLaw(law, [&](auto law_tag) { result = runLoop<decltype(law_tag)>(run, cfg, iterations, observe); });
  return result;
}

// The study's run: its task's iterations (studyIterationCount).
template <typename T, typename Observer = NoObserver>
RunnerResult runStudy(LawType law, const ArdroneRun<T>& run, const RunnerConfig<T>& cfg,
                      Observer observe = Observer()) {
  const long n = studyIterationCount(double(cfg.task.duration()), double(run.plant.Ts));
  return runLoop(law, run, cfg, n, observe);
}

// The delay study's PD law on drone `p` (the thesis's runs).
template <typename T, typename Observer = NoObserver>
RunnerResult runPositioning(const LawVehicle::Params<T>& p, const RunnerConfig<T>& cfg,
                            const PdGains<T>& gains, long delay, Observer observe = Observer()) {
  ArdroneRun<T> run{p, p, LawGains<T>{gains, UnderactuatedGains<T>::defaults()}, delay};
  return runStudy(LawType::kPdSaturated, run, cfg, observe);
}

}  // namespace aurora_control
