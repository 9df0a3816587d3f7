// The predictor in the one loop (docs/predictor.md, "In the loop"): the
// iteration (closed_loop.h's loopIteration) stays as it is; its history
// and link policies are wrapped. The history keeps the vehicle's whole
// states and reads back, for the step the link delivered, the predictor's
// state (the law flies on it, the metrics count its error); the link tells
// the predictor each command the controller sends before passing it on.
// The vehicle's half and its checks see the true state, as the safety
// layer does on a robot.
#pragma once

#include <memory>

#include "aurora_control/loop/positioning_runner.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/predictor/state_predictor.h"

namespace aurora_control {

// A "law" that reads every state of vehicle V: the history of the states
// the predictor starts from (closed_loop.h's StateHistory keeps what a law
// reads; the model needs all of it).
template <class V>
struct WholeStateReader {
  using Vehicle = V;
  struct Input {
    static constexpr int kWidth = V::kStates;
    AURORA_HD static constexpr int state(int j) { return j; }
  };
};

// The predictor of the host's loops (the offline runner, the node): rings
// for any history the node's limit allows (predictor_yaml.h refuses more).
template <class Vehicle, typename T>
using HostPredictor = StatePredictor<Vehicle, T, 2 * kDelayHistory>;

template <class Vehicle, typename T, int Capacity, class Predictor>
class PredictedHistory {
 public:
  AURORA_HD explicit PredictedHistory(Predictor& predictor) : predictor_(predictor) {}
  AURORA_HD void push(const T X[Vehicle::kStates]) {
    states_.push(X);
    ++k_;
  }
  // The state the controller flies on at this iteration, the state of
  // step `received` having arrived.
  AURORA_HD void read(long received, T X[Vehicle::kStates]) {
    T xc[Vehicle::kStates];
    states_.read(received, xc);
    predictor_.predict(k_, received, xc, X);
  }

 private:
  Predictor& predictor_;
  StateHistory<WholeStateReader<Vehicle>, T, Capacity> states_;
  long k_ = -1;  // the iteration: one push each
};

template <class Predictor, class Link>
struct PredictedLink {
  Predictor& predictor;
  Link& link;
  AURORA_HD long uplinkIndex(long k) { return link.uplinkIndex(k); }
  template <typename T>
  AURORA_HD void downlink(long k, const T* sent, T* received) {
    predictor.sent(k, sent);
    link.downlink(k, sent, received);
  }
};

// Runs loopIteration with `predictor` over `link` (host, scalar loop and
// CUDA thread alike: nothing allocated here).
template <class Law, typename T, int Capacity, typename Observer, class Predictor, typename Link>
AURORA_HD RunnerResult runPredictedOver(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg,
                                        long iterations, Observer& observe, Predictor& predictor, Link& link) {
  PredictedHistory<typename Law::Vehicle, T, Capacity, Predictor> history(predictor);
  PredictedLink<Predictor, Link> predicted{predictor, link};
  return runClosedLoopWith<Law>(run, cfg, iterations, observe, history, predicted);
}

// runLoop (positioning_runner.h) with the predictor `p` when it is on.
template <class Law, typename T, typename Observer = NoObserver>
RunnerResult runLoop(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg,
                     const PredictorRun<typename Law::Vehicle, T>& p, long iterations, Observer observe = Observer()) {
  if (!p.on()) return runLoop<Law>(run, cfg, iterations, observe);
  RunnerResult result;
  std::unique_ptr<HostPredictor<typename Law::Vehicle, T>> predictor(
      new HostPredictor<typename Law::Vehicle, T>(p.form, p.model, p.path));
  withLoopLink<Law>(run, cfg, [&](auto capacity, auto& link) {
    result = runPredictedOver<Law, T, decltype(capacity)::value>(run, cfg, iterations, observe, *predictor, link);
  });
  return result;
}

}  // namespace aurora_control
