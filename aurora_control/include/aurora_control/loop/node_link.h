// The link in the controller node's incremental form (docs/links.md): the
// offline runner's ModelLink (loop_link.h), fed one state step at a time as
// states arrive (a step the node never received is a packet never sent) and
// one command per step (the first computed in that step; a timer cycle
// without a new state re-sends nothing). The node and replay use it through
// DelayedController, so a lockstep flight over a lossy, jittery link equals
// the offline runner's bit for bit.
#pragma once

#include <memory>

#include "aurora_control/loop/loop_link.h"

namespace aurora_control {

template <int Capacity>
class NodeLink {
 public:
  // An ideal link (link.ideal()) leaves the node on the delay rule; any
  // other starts the channels afresh (a changed link, a source reset).
  // `key`: what the draws are keyed by besides the seed (a formation's
  // drone index; 0 for one drone), as the offline runners key them.
  void configure(const LinkParams& link, long delay, double Ts, uint64_t key = 0) {
    params_ = link, delay_ = delay, Ts_ = Ts, key_ = key;
    reset();
  }

  void reset() {
    model_.reset(params_.ideal() ? nullptr : new ModelLink<Capacity, double>(params_, delay_, key_, Ts_));
    up_step_ = down_step_ = used_ = -1;
    arrived_ = false;
    for (double& u : drone_) u = 0.0;
  }

  bool active() const { return model_ != nullptr; }
  void setDelay(long delay) {
    delay_ = delay;
    if (model_) model_->setUplinkDelay(delay);
  }

  // The state of step k arrived (steps in increasing order). Returns the
  // step of the state the controller uses from now on.
  long stateReceived(long k) {
    for (long j = firstMissing(up_step_, k); j < k; ++j) model_->uplinkMiss(j);
    const long used = model_->uplinkIndex(k);
    arrived_ = used != used_;
    used_ = used, up_step_ = k;
    return used_;
  }

  // The command the controller sends at step k; `drone`: what the drone
  // applies (the same for every call within step k).
  void commandSent(long k, const double sent[4], double drone[4]) {
    if (k != down_step_) {
      for (long j = firstMissing(down_step_, k); j < k; ++j) model_->downlinkMiss(j);
      model_->downlink(k, sent, drone_);
      down_step_ = k;
    }
    for (int i = 0; i < 4; ++i) drone[i] = drone_[i];
  }

  bool stateArrived() const { return arrived_; }  // the last state step brought a newer state
  // Steps since the command the drone applies was sent (-1: none yet).
  long commandAge(long k) const {
    const long j = model_->downlinkChannel().newest();
    return j < 0 ? -1 : k - j;
  }
  bool droneHovers() const { return model_->hovering(); }
  long uplinkLosses() const { return model_->uplinkChannel().losses(); }
  long downlinkLosses() const { return model_->downlinkChannel().losses(); }

 private:
  // Steps after `last` before k without a packet; only the last Capacity
  // matter (the channels track no more), so a first state of step 10^9 does
  // not loop 10^9 times.
  static long firstMissing(long last, long k) { return last + 1 > k - Capacity ? last + 1 : k - Capacity; }

  LinkParams params_;
  long delay_ = 0;
  double Ts_ = 1.0 / 30.0;
  uint64_t key_ = 0;
  std::unique_ptr<ModelLink<Capacity, double>> model_;
  long up_step_ = -1, down_step_ = -1, used_ = -1;
  bool arrived_ = false;
  double drone_[4] = {0, 0, 0, 0};
};

}  // namespace aurora_control
