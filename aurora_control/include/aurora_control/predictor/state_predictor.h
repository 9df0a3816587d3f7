// The state predictor (docs/predictor.md): from the newest state the
// controller received (its step a, the "anchor") and the commands it sent
// since, a model of the vehicle predicts the state at the step its new
// command will act on, k + command delay (+ a fixed horizon on real
// robots), and the law flies on that prediction. Two forms
// (docs/predictor.md, eqs. P1 and P2):
// - resimulate: the model's whole state kept at the anchor (its published
//   states the received ones) and run forward over the commands applied
//   (cost: the anchor's age in model steps);
// - smith: the anchor's state plus the open-loop model's change since
//   (one model step per iteration, whatever the age).
// Generic in the vehicle (its State, step, limitInput); ROS-free, no clock
// (the caller passes the step numbers), no allocation: fixed rings of
// `Window` steps, so it runs in the offline runner, the node, the sweep's
// scalar loop and each CUDA thread alike.
#pragma once

#include "aurora_common/host_device.h"

namespace aurora_control {

enum class PredictorForm { kOff, kResimulate, kSmith };

inline const char* predictorFormName(PredictorForm f) {
  return f == PredictorForm::kResimulate ? "resimulate" : f == PredictorForm::kSmith ? "smith" : "off";
}

// How the command path looks from the controller (docs/predictor.md, "The
// commands applied"): the command sent at step j acts at step j + delay
// (the link's downlink base delay, 0 over an ideal link); `horizon`
// further steps the loop cannot see (a real robot's latency), over which
// the last command sent is held; `clamp`: the vehicle clamps what it
// receives.
struct CommandPath {
  long delay = 0;    // [samples]
  long horizon = 0;  // [samples]
  bool clamp = false;
};

template <class Vehicle, typename T, int Window>
class StatePredictor {
 public:
  using Params = typename Vehicle::template Params<T>;
  using State = typename Vehicle::template State<T>;
  static constexpr int kStates = Vehicle::kStates, kInputs = Vehicle::kInputs;

  // The model starts as the vehicle does (Vehicle::start). The caller
  // keeps a received state's age plus the command delay below Window
  // (predictor_yaml.h refuses a horizon beyond the history; a sweep's
  // window is twice its history).
  AURORA_HD StatePredictor(PredictorForm form, const Params& model, const CommandPath& path)
      : form_(form), model_(model), path_(path) {
    Vehicle::start(model_, anchor_);
    open_ = anchor_;
    for (int i = 0; i < kStates; ++i) open_X_[0][i] = open_.X[i];
  }

  // Iteration k: the state xc of step `received` (<= k) arrived; xp: the
  // state predicted for step target() from the newest state received.
  // Off (a formation robot whose controller file has none, beside one
  // that has): the received state as it is.
  AURORA_HD void predict(long k, long received, const T xc[kStates], T xp[kStates]) {
    k_ = k;
    if (form_ == PredictorForm::kOff) {
      for (int i = 0; i < kStates; ++i) xp[i] = xc[i];
      return;
    }
    if (form_ != PredictorForm::kSmith) keepCommandsInRing();
    receive(received, xc);
    if (form_ == PredictorForm::kSmith) return smith(xp);
    State s = anchor_;
    for (long j = anchor_step_; j < target(); ++j) stepModel(s, j);  // eq. P1
    for (int i = 0; i < kStates; ++i) xp[i] = s.X[i];
  }

  // The command the controller sent at iteration k (after its clamp). A
  // step it sent nothing at (the node's cycles need not meet every state
  // step) holds the command before it, as the vehicle does.
  AURORA_HD void sent(long k, const T U[kInputs]) {
    for (long j = last_sent_ + 1; j < k && last_sent_ >= 0 && j > k - Window; ++j) {
      for (int i = 0; i < kInputs; ++i) sent_[index(j)][i] = sent_[index(j - 1)][i];
    }
    for (int i = 0; i < kInputs; ++i) sent_[index(k)][i] = U[i];
    if (k > last_sent_) last_sent_ = k;
  }

  AURORA_HD long target() const { return k_ + path_.delay + path_.horizon; }
  // The step of the newest state received (the prediction's start).
  AURORA_HD long anchor() const { return anchor_step_; }

 private:
  AURORA_HD static long index(long step) { return step % Window; }

  // The command the vehicle applies at step j as the controller sees it:
  // the one sent at j - delay (none yet: zero, the link's hover), the last
  // sent for a step it has not sent yet (the horizon), clamped if the
  // vehicle clamps.
  AURORA_HD void applied(long j, T U[kInputs]) const {
    const long s = j - path_.delay < last_sent_ ? j - path_.delay : last_sent_;
    for (int i = 0; i < kInputs; ++i) {
      const T u = s < 0 ? T(0) : sent_[index(s)][i];
      U[i] = path_.clamp ? Vehicle::limitInput(model_, i, u) : u;
    }
  }

  AURORA_HD void stepModel(State& s, long j) const {
    T U[kInputs];
    applied(j, U);
    Vehicle::step(model_, s, U);
  }

  // A newer state moves the anchor, its published states the received ones;
  // for resimulate the model's whole state is stepped to it first (the
  // vehicle's unpublished channels, e.g. the AR.Drone's motors, stay the
  // model's; smith keeps only the received states). An older one (the delay
  // rule's start, a late packet) leaves the newer anchor. A step more than
  // a window ahead (the node's first state of a source that ran before)
  // keeps the model's channels as they are.
  AURORA_HD void receive(long r, const T xc[kStates]) {
    if (r < anchor_step_) return;
    if (r - anchor_step_ >= Window || form_ == PredictorForm::kSmith) anchor_step_ = r;
    for (; anchor_step_ < r; ++anchor_step_) stepModel(anchor_, anchor_step_);
    for (int i = 0; i < kStates; ++i) anchor_.X[i] = xc[i];
  }

  // Resimulate across a long outage (no newer state for about a window):
  // before a state is received, the anchor steps along the model over each
  // command about to leave the ring (up to the one of step k - Window, which
  // sent(k) overwrites), so the prediction steps the same model over the
  // same commands, to the bit, as with an endless ring. Nothing sent yet:
  // nothing to keep (receive's rule for a first state far ahead holds); a
  // cycle more than a window after the last: the anchor jumps, as there.
  AURORA_HD void keepCommandsInRing() {
    const long first_kept = k_ - Window + path_.delay + 1;
    if (last_sent_ < 0) return;
    if (first_kept - anchor_step_ >= Window) anchor_step_ = first_kept;
    for (; anchor_step_ < first_kept; ++anchor_step_) stepModel(anchor_, anchor_step_);
  }

  // Eq. P2: xp = x_a + (m_N - m_a), m the model open loop on the commands
  // applied (its states kept by step up to those all sent, k + delay). m_a
  // is copied before the open loop's ring overwrites it (a long outage).
  AURORA_HD void smith(T xp[kStates]) {
    const long sent_through = k_ + path_.delay;
    if (sent_through - open_step_ >= Window) open_step_ = sent_through - 1;
    for (; open_step_ < sent_through; ++open_step_) {
      stepModel(open_, open_step_);
      if (open_step_ + 1 - Window == anchor_step_) keepOpenAtAnchor();
      for (int i = 0; i < kStates; ++i) open_X_[index(open_step_ + 1)][i] = open_.X[i];
    }
    State ahead = open_;
    for (long j = open_step_; j < target(); ++j) stepModel(ahead, j);
    const T* then = kept_step_ == anchor_step_ ? kept_X_ : open_X_[index(anchor_step_)];
    for (int i = 0; i < kStates; ++i) xp[i] = anchor_.X[i] + (ahead.X[i] - then[i]);
  }
  AURORA_HD void keepOpenAtAnchor() {
    for (int i = 0; i < kStates; ++i) kept_X_[i] = open_X_[index(anchor_step_)][i];
    kept_step_ = anchor_step_;
  }

  PredictorForm form_;
  Params model_;
  CommandPath path_;
  T sent_[Window][kInputs] = {};  // the commands sent, by step
  long last_sent_ = -1;           // the newest step sent
  State anchor_;                  // the newest state received (resimulate: the model's whole state there)
  long anchor_step_ = 0;
  State open_;                    // smith: the model open loop, at open_step_
  T open_X_[Window][kStates];     // its states by step
  long open_step_ = 0;
  T kept_X_[kStates] = {};        // smith: its state at the anchor, once the ring let it go
  long kept_step_ = -1;
  long k_ = 0;
};

// The predictor's settings for a run (docs/predictor.md, "Configuration"):
// its form, its model of the vehicle (the nominal vehicle file; the plant
// may differ) and the command path it predicts over.
template <class Vehicle, typename T>
struct PredictorRun {
  PredictorForm form = PredictorForm::kOff;
  typename Vehicle::template Params<T> model;
  CommandPath path;
  AURORA_HD bool on() const { return form != PredictorForm::kOff; }
  // The same predictor in precision U (a sweep's).
  template <typename U>
  PredictorRun<Vehicle, U> cast() const {
    return PredictorRun<Vehicle, U>{form, model.template cast<U>(), path};
  }
};

}  // namespace aurora_control
