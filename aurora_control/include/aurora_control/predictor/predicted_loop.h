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

template <class Vehicle, typename T, int Capacity>
class PredictedHistory {
 public:
  explicit PredictedHistory(StatePredictor<Vehicle, T>& predictor) : predictor_(predictor) {}
  void push(const T X[Vehicle::kStates]) {
    states_.push(X);
    ++k_;
  }
  // The state the controller flies on at this iteration, the state of
  // step `received` having arrived.
  void read(long received, T X[Vehicle::kStates]) {
    T xc[Vehicle::kStates];
    states_.read(received, xc);
    predictor_.predict(k_, received, xc, X);
  }

 private:
  StatePredictor<Vehicle, T>& predictor_;
  StateHistory<WholeStateReader<Vehicle>, T, Capacity> states_;
  long k_ = -1;  // the iteration: one push each
};

template <class Vehicle, typename T, class Link>
struct PredictedLink {
  StatePredictor<Vehicle, T>& predictor;
  Link& link;
  long uplinkIndex(long k) { return link.uplinkIndex(k); }
  void downlink(long k, const T* sent, T* received) {
    predictor.sent(k, sent);
    link.downlink(k, sent, received);
  }
};

// The predictor's settings for a run (docs/predictor.md, "Configuration"):
// its form, its model of the vehicle (the nominal vehicle file; the plant
// may differ) and the command path it predicts over.
template <class Vehicle, typename T>
struct PredictorRun {
  PredictorForm form = PredictorForm::kOff;
  typename Vehicle::template Params<T> model;
  CommandPath path;
  bool on() const { return form != PredictorForm::kOff; }
};

// The predictor's rings: the history, the command delay and horizon, and
// one to spare.
inline long predictorWindow(long history, const CommandPath& path) { return history + path.delay + path.horizon + 2; }

// Runs loopIteration with the predictor over `link` (host: the rings on the
// heap).
template <class Law, typename T, int Capacity, typename Observer, typename Link>
RunnerResult runPredictedOver(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg,
                              const PredictorRun<typename Law::Vehicle, T>& p, long iterations, Observer& observe,
                              Link& link) {
  using Vehicle = typename Law::Vehicle;
  StatePredictor<Vehicle, T> predictor(p.form, p.model, p.path, predictorWindow(Capacity, p.path));
  std::unique_ptr<PredictedHistory<Vehicle, T, Capacity>> history(
      new PredictedHistory<Vehicle, T, Capacity>(predictor));
  PredictedLink<Vehicle, T, Link> predicted{predictor, link};
  return runClosedLoopWith<Law>(run, cfg, iterations, observe, *history, predicted);
}

// runLoop (positioning_runner.h) with the predictor `p` when it is on.
template <class Law, typename T, typename Observer = NoObserver>
RunnerResult runLoop(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg,
                     const PredictorRun<typename Law::Vehicle, T>& p, long iterations, Observer observe = Observer()) {
  if (!p.on()) return runLoop<Law>(run, cfg, iterations, observe);
  RunnerResult result;
  withLoopLink<Law>(run, cfg, [&](auto capacity, auto& link) {
    result = runPredictedOver<Law, T, decltype(capacity)::value>(run, cfg, p, iterations, observe, link);
  });
  return result;
}

}  // namespace aurora_control
