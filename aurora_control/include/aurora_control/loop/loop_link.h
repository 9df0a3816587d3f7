// The link between the loop's two halves, as the offline runner uses it
// (docs/links.md): which state the controller receives at step k, and which
// command the drone applies. Two policies with one interface:
// - IdealLink: today's loop, the delay rule on the uplink (delay_buffer.h)
//   and the sent command applied at once; nothing to draw, nothing to store
//   (the CUDA kernel and the SIMD engine's loop);
// - ModelLink: link.h's channels on both directions, a ring of the commands
//   sent, the drone's hover when none has arrived or the newest is stale.
// With a constant uplink delay, no jitter, no loss and no downlink delay
// both give the same bits (a test checks it).
#pragma once

#include <cmath>
#include <cstdint>

#include "aurora_control/loop/delay_buffer.h"
#include "aurora_control/link/link.h"

namespace aurora_control {

// `Index`: long for one run, integer lanes (the SIMD engine) for many.
template <typename Index>
struct IdealLinkOf {
  Index delay;  // the uplink's [samples]

  // The step whose state the controller receives at step k (0-based): the
  // delay rule, k - d once k >= d, else the current state.
  AURORA_HD Index uplinkIndex(const Index& k) const {
    return delayedHistoryIndex<Index>(k + Index(1), delay) - Index(1);
  }

  // The command arrives as sent (the loop passes it in place: nothing to do).
  template <typename T>
  AURORA_HD void downlink(const Index&, const T*, T*) const {}
};
using IdealLink = IdealLinkOf<long>;

// `Inputs`: the vehicle's command size (its kInputs).
template <int Window, typename T, int Inputs = 4>
class ModelLink {
 public:
  // `delay`: the run's (uplink) delay, which replaces the link's own.
  AURORA_HD ModelLink(const LinkParams& link, long delay, uint64_t combination, double Ts)
      : link_(link), combination_(combination), up_rule_(LossRule::of(link.uplink)),
        down_rule_(LossRule::of(link.downlink)) {
    link_.uplink.delay = delay;
    timeout_steps_ = static_cast<long>(std::lround(link.cmd_timeout / Ts));
  }

  // The controller's state at step k: the newest-sent state that has
  // arrived, the current one while none has (the start rule).
  AURORA_HD long uplinkIndex(long k) {
    up_.send(link_.uplink, up_rule_, drawsAt(k).uplink, k);
    const long j = up_.receive(link_.uplink, k);
    return j < 0 ? k : j;
  }

  // The drone's command at step k: the newest-sent command that has
  // arrived, or hover (zero) while none has or when the newest arrived
  // cmd_timeout or longer ago (the drivers' watchdog).
  AURORA_HD void downlink(long k, const T sent[Inputs], T received[Inputs]) {
    for (int i = 0; i < Inputs; ++i) commands_[k % Window][i] = sent[i];
    down_.send(link_.downlink, down_rule_, drawsAt(k).downlink, k);
    const long j = down_.receive(link_.downlink, k);
    hovering_ = hoverMask<long>(j, down_.sinceArrival(k), timeout_steps_) != 0;
    for (int i = 0; i < Inputs; ++i) received[i] = hovering_ ? T(0) : commands_[j % Window][i];
  }

  // A step without a packet on a direction (the node: a state it never
  // received, a step without a command).
  AURORA_HD void uplinkMiss(long k) { up_.miss(k); }
  AURORA_HD void downlinkMiss(long k) { down_.miss(k); }
  // The uplink's base delay changed (a live change of the node's delay).
  AURORA_HD void setUplinkDelay(long delay) { link_.uplink.delay = delay; }

  // The drone hovers at the last downlink step (no command, or a stale one).
  AURORA_HD bool hovering() const { return hovering_; }

  AURORA_HD const LinkChannel<Window>& uplinkChannel() const { return up_; }
  AURORA_HD const LinkChannel<Window>& downlinkChannel() const { return down_; }

 private:
  // Step k's draws, one Philox block for both directions (computed once per
  // step, and only when some direction draws).
  AURORA_HD const StepDraws& drawsAt(long k) {
    if (drawn_step_ != k && !(link_.uplink.constant() && link_.downlink.constant())) {
      draws_ = stepDraws(link_.seed, combination_, static_cast<uint64_t>(k));
      drawn_step_ = k;
    }
    return draws_;
  }


  LinkParams link_;
  uint64_t combination_;
  long timeout_steps_;
  bool hovering_ = false;
  LossRule up_rule_, down_rule_;  // the directions' loss rules (a live change builds a new link)
  long drawn_step_ = -1;
  StepDraws draws_{};
  LinkChannel<Window> up_, down_;
  T commands_[Window][Inputs];
};

}  // namespace aurora_control
