// The state predictor (docs/predictor.md): from the state the controller
// received (step r, age k - r) and the commands it sent since, a model of
// the vehicle predicts the state at the step its new command will act on,
// k + command delay (+ a fixed horizon on real robots), and the law flies
// on that prediction. Two forms (docs/predictor.md, eqs. P1 and P2):
// - resimulate: the model run forward from the received state over the
//   commands applied since (cost: the age in model steps);
// - smith: the received state plus the open-loop model's change since r
//   (one model step per iteration, whatever the age).
// Generic in the vehicle (its State, step, limitInput); ROS-free, no clock:
// the caller passes the step numbers. One run at a time (host): the rings
// live on the heap with the predictor (a run of 2048 samples of history
// keeps 4096 whole states).
#pragma once

#include <algorithm>
#include <vector>

namespace aurora_control {

enum class PredictorForm { kOff, kResimulate, kSmith };

inline const char* predictorFormName(PredictorForm f) {
  return f == PredictorForm::kResimulate ? "resimulate" : f == PredictorForm::kSmith ? "smith" : "off";
}

// How the command path looks from the controller (docs/predictor.md, "The
// commands applied"): the command sent at step j acts at step j + delay
// (the link's downlink delay, 0 over an ideal link); `horizon` further
// steps the loop cannot see (a real robot's latency), over which the last
// command sent is held; `clamp`: the vehicle clamps what it receives.
struct CommandPath {
  long delay = 0;    // [samples]
  long horizon = 0;  // [samples]
  bool clamp = false;
};

template <class Vehicle, typename T>
class StatePredictor {
 public:
  using Params = typename Vehicle::template Params<T>;
  using State = typename Vehicle::template State<T>;
  static constexpr int kStates = Vehicle::kStates, kInputs = Vehicle::kInputs;

  // `window`: more than the largest age a received state may have plus the
  // command delay (the caller's history plus the delay; checked by the
  // caller). The model starts as the vehicle does (Vehicle::start).
  StatePredictor(PredictorForm form, const Params& model, const CommandPath& path, long window)
      : form_(form), model_(model), path_(path), window_(window), sent_(window), states_(window) {
    Vehicle::start(model_, states_[0]);
  }

  // Iteration k: the state xc of step `received` (<= k) arrived; xp: the
  // state predicted for step k + delay + horizon.
  void predict(long k, long received, const T xc[kStates], T xp[kStates]) {
    k_ = k;
    if (form_ == PredictorForm::kSmith) return smith(received, xc, xp);
    resimulate(received, xc, xp);
  }

  // The command the controller sent at iteration k (after its clamp).
  // A step the controller sent nothing at (the node's cycles need not
  // meet every state step) holds the command before it, as the vehicle does.
  void sent(long k, const T U[kInputs]) {
    for (long j = std::max(last_sent_ + 1, k - window_ + 1); j < k && last_sent_ >= 0; ++j) {
      sent_[index(j)] = sent_[index(j - 1)];
    }
    std::copy(U, U + kInputs, sent_[index(k)].u);
    last_sent_ = std::max(last_sent_, k);
  }

  long target() const { return k_ + path_.delay + path_.horizon; }

 private:
  struct Command {
    T u[kInputs];
  };

  long index(long step) const { return step % window_; }

  // The command the vehicle applies at step j as the controller sees it:
  // the one sent at j - delay (none yet: zero, the link's hover), the last
  // sent for a step it has not sent yet (the horizon), clamped if the
  // vehicle clamps.
  void applied(long j, T U[kInputs]) const {
    const long s = std::min(j - path_.delay, last_sent_);
    for (int i = 0; i < kInputs; ++i) {
      const T u = s < 0 ? T(0) : sent_[index(s)].u[i];
      U[i] = path_.clamp ? Vehicle::limitInput(model_, i, u) : u;
    }
  }

  // The model's whole state of step j, stepped on from the newest kept.
  // A step more than a window ahead (the node's first state of a source
  // that ran before) starts from the newest state kept.
  void extendTo(long j) {
    if (j - newest_ >= window_) {
      states_[index(j)] = states_[index(newest_)];
      newest_ = j;
    }
    for (; newest_ < j; ++newest_) {
      State s = states_[index(newest_)];
      stepModel(s, newest_);
      states_[index(newest_ + 1)] = s;
    }
  }

  void stepModel(State& s, long j) const {
    T U[kInputs];
    applied(j, U);
    Vehicle::step(model_, s, U);
  }

  // Eq. P1: the received state in the model's state of its step (the
  // vehicle's other channels, e.g. the AR.Drone's motors, the model's),
  // stepped to the target; the steps whose commands are all sent are kept
  // (a later state received from them starts from there).
  void resimulate(long r, const T xc[kStates], T xp[kStates]) {
    extendTo(r);
    State s = states_[index(r)];
    std::copy(xc, xc + kStates, s.X);
    states_[index(r)] = s;
    const long kept = k_ + path_.delay;  // the commands of steps below it are all sent
    for (long j = r; j < target(); ++j) {
      stepModel(s, j);
      if (j + 1 <= kept) states_[index(j + 1)] = s;
    }
    newest_ = kept;  // >= r: r <= k
    std::copy(s.X, s.X + kStates, xp);
  }

  // Eq. P2: xp = xc + (model at the target - model at r), the model open
  // loop on the commands applied (states_ keep its states, newest_ its step
  // up to the commands sent).
  void smith(long r, const T xc[kStates], T xp[kStates]) {
    extendTo(k_ + path_.delay);
    State ahead = states_[index(newest_)];
    for (long j = newest_; j < target(); ++j) stepModel(ahead, j);
    const State& then = states_[index(r)];
    for (int i = 0; i < kStates; ++i) xp[i] = xc[i] + (ahead.X[i] - then.X[i]);
  }

  PredictorForm form_;
  Params model_;
  CommandPath path_;
  long window_;
  std::vector<Command> sent_;  // the commands sent, by step
  std::vector<State> states_;  // the model's whole states, by step
  long newest_ = 0;      // the newest step in states_
  long last_sent_ = -1;  // the newest step sent
  long k_ = 0;
};

}  // namespace aurora_control
