// One robot's link in a formation flight's own loop (the UAV-UGV line's,
// the triangle's; docs/formation.md): the delay rule over an ideal link
// (AuRoRA's, bit for bit), or its link model (docs/links.md) with the draws
// keyed by the robot's index, as the two-drone line's robots. Host only.
#pragma once

#include <cstdint>
#include <memory>

#include "aurora_control/link/link.h"
#include "aurora_control/loop/loop_link.h"
#include "aurora_control/params/limits.h"

namespace aurora_control {

template <int Inputs>
class RobotLink {
 public:
  RobotLink(const LinkParams& link, long delay, uint64_t robot, double Ts) : ideal_{delay} {
    if (!link.ideal()) model_.reset(new ModelLink<kDelayHistory, double, Inputs>(link, delay, robot, Ts));
  }

  // The step whose state the controller has at step k. Asked again for the
  // same step (a layer and a law reading one step), the same answer: the
  // link model sends each step's packet once.
  long uplinkIndex(long k) {
    if (k != asked_) asked_ = k, answer_ = model_ ? model_->uplinkIndex(k) : ideal_.uplinkIndex(k);
    return answer_;
  }
  // The command the robot applies at step k (as sent over an ideal link).
  void downlink(long k, const double sent[Inputs], double received[Inputs]) {
    if (model_) model_->downlink(k, sent, received);
    else if (received != sent) for (int i = 0; i < Inputs; ++i) received[i] = sent[i];
  }

 private:
  IdealLink ideal_;
  std::unique_ptr<ModelLink<kDelayHistory, double, Inputs>> model_;  // on the heap: Capacity-sized rings
  long asked_ = -1, answer_ = 0;
};

}  // namespace aurora_control
