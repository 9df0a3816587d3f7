// The state predictor on the SIMD engine's lanes (docs/predictor.md, "In a
// sweep"): aurora_control's StatePredictor, the same rules, each lane its
// own run. Each lane's anchor (the newest state it received, the model's
// whole state there) and its open-loop model are batches; each lane steps
// as many model steps as its own age asks, the batch as many as the oldest
// lane's (the others keep their states: masked). The commands sent and the
// open loop's states sit in rings of slots [slot][i][lane] as the history's
// (lane_history.h): every lane writes the same slot at a step, lane l's
// step j sits at slot base_l + j. Included by batch_engine.h only.
#pragma once

#include <xsimd/xsimd.hpp>

#include <vector>

#include "aurora_control/loop/predicted_loop.h"
#include "gather_lanes.h"
#include "lane_history.h"

namespace aurora_sweep {

namespace {

template <class Vehicle, typename T, class Arch>
class LanePredictor {
 public:
  using B = xsimd::batch<T, Arch>;
  using M = xsimd::batch_bool<T, Arch>;
  using Int = xsimd::as_integer_t<T>;
  using I = xsimd::batch<Int, Arch>;
  using State = typename Vehicle::template State<B>;
  static constexpr int L = static_cast<int>(B::size);
  static constexpr int kStates = Vehicle::kStates, kInputs = Vehicle::kInputs;
  static constexpr int kStateBatches = static_cast<int>(sizeof(State) / sizeof(B));
  static_assert(sizeof(State) == kStateBatches * sizeof(B), "a vehicle state is a struct of its scalar only");

  // `start`: the vehicle's state at the start (every lane's, scalar);
  // rings of `window` slots (a power of two).
  LanePredictor(aurora_control::PredictorForm form, const typename Vehicle::template Params<T>& model,
                const typename Vehicle::template State<T>& start, bool clamp, long window)
      : form_(form), model_(model.template cast<B>()), clamp_(clamp), start_(start), mask_(window - 1),
        sent_(static_cast<size_t>(window) * kInputs * L, T(0)), open_X_(static_cast<size_t>(window) * kStates * L) {
    alignas(64) Int iota[L];
    for (int l = 0; l < L; ++l) iota[l] = static_cast<Int>(l);
    lane_ = I::load_aligned(iota);
    for (int i = 0; i < kStates; ++i) kept_X_[i] = B(T(0));
  }

  // Lane l starts a run whose step 0 is the next one pushed, with command
  // delay `delay` [samples].
  void startLane(int l, long delay) {
    Lanes<T, Arch>::set(base_, l, static_cast<Int>(pushed_ + 1));
    Lanes<T, Arch>::set(delay_, l, static_cast<Int>(delay));
    Lanes<T, Arch>::set(anchor_step_, l, Int(0));
    Lanes<T, Arch>::set(open_step_, l, Int(0));
    Lanes<T, Arch>::set(kept_step_, l, Int(-1));
    Lanes<T, Arch>::setFields(anchor_, l, start_);
    Lanes<T, Arch>::setFields(open_, l, start_);
    storeLane(l, pushed_ + 1, start_.X);  // the open loop's step 0
  }

  // Every lane pushed its step k (the history's push).
  void pushed() { ++pushed_; }

  // Each lane at its step k received the state xc of its step r.
  // Off: the received state as it is (StatePredictor::predict's rule).
  void predict(const I& k, const I& r, const B xc[kStates], B xp[kStates]) {
    k_ = k;
    if (form_ == aurora_control::PredictorForm::kOff) {
      for (int i = 0; i < kStates; ++i) xp[i] = xc[i];
      return;
    }
    if (form_ != aurora_control::PredictorForm::kSmith) keepCommandsInRing();
    receive(r, xc);
    if (form_ == aurora_control::PredictorForm::kSmith) return smith(xp);
    State s = anchor_;
    steppedTo(s, anchor_step_, target(), nullptr);  // eq. P1
    for (int i = 0; i < kStates; ++i) xp[i] = s.X[i];
  }

  // The commands every lane sent at its step k (all at this push's slot).
  void sent(const B U[kInputs]) {
    const long slot = pushed_ & mask_;
    for (int i = 0; i < kInputs; ++i) U[i].store_unaligned(&sent_[(slot * kInputs + i) * L]);
  }

 private:
  I target() const { return k_ + delay_; }
  I slotOf(const I& step) const { return (base_ + step) & I(static_cast<Int>(mask_)); }

  // What each lane's vehicle applies at its step j (StatePredictor::applied).
  void applied(const I& j, B U[kInputs]) const {
    const I s = xsimd::min(j - delay_, k_ - I(Int(1)));
    const M none = xsimd::bool_cast(s < I(Int(0)));
    const I at = slotOf(xsimd::max(s, I(Int(0)))) * I(Int(kInputs * L)) + lane_;
    for (int i = 0; i < kInputs; ++i) {
      const B u = xsimd::select(none, B(T(0)), gatherLanes<B>(sent_.data(), at + I(Int(i * L))));
      U[i] = clamp_ ? Vehicle::limitInput(model_, i, u) : u;
    }
  }

  // Each lane's s stepped from its step `from` to its step `to` (none where
  // from >= to); with `keep`, each state reached is stored in the open
  // loop's ring.
  void steppedTo(State& s, I from, const I& to, std::vector<T>* keep) {
    for (M go = xsimd::bool_cast(from < to); xsimd::any(go); go = xsimd::bool_cast(from < to)) {
      State next = s;
      B U[kInputs];
      applied(from, U);
      Vehicle::step(model_, next, U);
      selectState(go, next, s);
      from = from + xsimd::select(xsimd::bool_cast(go), I(Int(1)), I(Int(0)));
      if (keep) keepStates(go, from, s);
    }
  }

  // The anchor moved to each lane's newer state (not to an older one); for
  // resimulate the model's whole state stepped to it first (smith keeps
  // only the received states), as StatePredictor::receive.
  void receive(const I& r, const B xc[kStates]) {
    if (form_ != aurora_control::PredictorForm::kSmith) steppedTo(anchor_, anchor_step_, r, nullptr);
    const M newer = xsimd::bool_cast(r >= anchor_step_);
    anchor_step_ = xsimd::max(anchor_step_, r);
    for (int i = 0; i < kStates; ++i) anchor_.X[i] = xsimd::select(newer, xc[i], anchor_.X[i]);
  }

  // Resimulate across a long outage: before a state is received, each
  // lane's anchor steps along the model over each command about to leave
  // the ring, as StatePredictor::keepCommandsInRing (the lanes send at every
  // step from their first).
  void keepCommandsInRing() {
    const I first_kept = k_ - I(static_cast<Int>(mask_ + 1)) + delay_ + I(Int(1));
    steppedTo(anchor_, anchor_step_, first_kept, nullptr);
    anchor_step_ = xsimd::max(anchor_step_, first_kept);
  }

  // Eq. P2 on every lane; m_a copied before the open loop's ring overwrites
  // it (keepStates), as StatePredictor::smith.
  void smith(B xp[kStates]) {
    steppedTo(open_, open_step_, k_ + delay_, &open_X_);
    open_step_ = xsimd::max(open_step_, k_ + delay_);
    State ahead = open_;
    const I at = slotOf(anchor_step_) * I(Int(kStates * L)) + lane_;
    const M kept = xsimd::bool_cast(kept_step_ == anchor_step_);
    for (int i = 0; i < kStates; ++i) {
      const B then = xsimd::select(kept, kept_X_[i], gatherLanes<B>(open_X_.data(), at + I(Int(i * L))));
      xp[i] = anchor_.X[i] + (ahead.X[i] - then);
    }
  }

  // The open loop's states of the lanes that stepped, at their new steps.
  void keepStates(const M& go, const I& step, const State& s) {
    alignas(64) bool lanes[L];
    go.store_aligned(lanes);
    alignas(64) Int steps[L];
    step.store_aligned(steps);
    alignas(64) T x[kStates][L];
    for (int i = 0; i < kStates; ++i) s.X[i].store_aligned(x[i]);
    for (int l = 0; l < L; ++l) {
      if (!lanes[l]) continue;
      T X[kStates];
      for (int i = 0; i < kStates; ++i) X[i] = x[i][l];
      const Int anchor = Lanes<T, Arch>::get(anchor_step_, l);
      if (steps[l] - (mask_ + 1) == anchor) keepOpenAtAnchor(l, anchor);  // its slot is the one written now
      storeLane(l, Lanes<T, Arch>::get(base_, l) + steps[l], X);
    }
  }
  void keepOpenAtAnchor(int l, Int anchor) {
    const long slot = (Lanes<T, Arch>::get(base_, l) + anchor) & mask_;
    for (int i = 0; i < kStates; ++i) Lanes<T, Arch>::set(kept_X_[i], l, open_X_[(slot * kStates + i) * L + l]);
    Lanes<T, Arch>::set(kept_step_, l, anchor);
  }
  void storeLane(int l, long slot, const T* X) {
    slot &= mask_;
    for (int i = 0; i < kStates; ++i) open_X_[(slot * kStates + i) * L + l] = X[i];
  }

  static void selectState(const M& go, const State& next, State& s) {
    const B* from = reinterpret_cast<const B*>(&next);
    B* to = reinterpret_cast<B*>(&s);
    for (int i = 0; i < kStateBatches; ++i) to[i] = xsimd::select(go, from[i], to[i]);
  }

  aurora_control::PredictorForm form_;
  typename Vehicle::template Params<B> model_;
  bool clamp_;
  typename Vehicle::template State<T> start_;
  long mask_;  // the rings' slots - 1
  std::vector<T, xsimd::aligned_allocator<T, 64>> sent_;  // [slot][input][lane]
  std::vector<T> open_X_;                                 // [slot][state][lane]
  I lane_, base_ = I(Int(0)), delay_ = I(Int(0));
  I k_ = I(Int(0)), anchor_step_ = I(Int(0)), open_step_ = I(Int(0));
  I kept_step_ = I(Int(-1));  // smith: the anchor step whose open-loop state kept_X_ holds, per lane
  B kept_X_[kStates];
  State anchor_, open_;  // the newest state received (resimulate: the model's whole state there); the open loop
  long pushed_ = 0;
};

// A worker without the predictor: nothing to keep.
struct NoLanePredictor {
  template <class... Args>
  explicit NoLanePredictor(const Args&...) {}
  void startLane(int, long) {}
};

// The vehicle's state at the start (Vehicle::start), of parameters p.
template <class Vehicle, typename T>
typename Vehicle::template State<T> vehicleStart(const typename Vehicle::template Params<T>& p) {
  typename Vehicle::template State<T> s;
  Vehicle::start(p, s);
  return s;
}

// The predictor in the engine's iteration: the whole-state history reads
// back each lane's prediction, the link tells it the commands sent.
template <class History, class Predictor>
struct PredictedLaneHistory {
  using B = typename History::B;
  using I = typename History::I;
  History& history;
  Predictor& predictor;
  void push(const B* X) {
    history.push(X);
    predictor.pushed();
  }
  void read(const I& received, B* X) {
    B xc[Predictor::kStates];
    history.read(received, xc);
    predictor.predict(history.size() - I(typename History::Int(1)), received, xc, X);
  }
};

template <class Link, class Predictor>
struct PredictedLaneLink {
  Link& link;
  Predictor& predictor;
  template <class K>
  K uplinkIndex(const K& k) {
    return link.uplinkIndex(k);
  }
  template <class K, class B>
  void downlink(const K& k, const B* sent, B* U) {
    predictor.sent(sent);
    link.downlink(k, sent, U);
  }
};

}  // namespace

}  // namespace aurora_sweep
