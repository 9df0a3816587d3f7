// Imperfect links (docs/links.md): per direction a base delay, a per-packet
// jitter, losses (independent or in bursts) and, on the command path, the
// drivers' hover on a stale command. ROS-free, header-only, host and device:
// the offline runner (and so the flight tool, the sweep's scalar backend and
// each CUDA thread) sends one packet per step on each direction and asks
// which one the receiver uses.
//
// Every random number is a pure function of (seed, combination, direction,
// step) (Random123's Philox4x32-10, counter-based), so any backend, any
// order of evaluation and the ROS loop draw the same numbers.
#pragma once

#include <Random123/philox.h>

#include <cmath>
#include <cstdint>

#include "aurora_common/host_device.h"

namespace aurora_control {

enum class JitterKind : int { kNone = 0, kUniform = 1, kGeometric = 2 };
enum class LinkDirectionId : uint32_t { kUplink = 0, kDownlink = 1 };

// One direction of a link (docs/links.md, "One direction").
struct LinkDirection {
  long delay = 0;                    // base delay [samples of Ts]
  JitterKind jitter = JitterKind::kNone;
  long jitter_max = 0;               // uniform: 0 ... max; geometric: cut at max [samples]
  double jitter_mean = 0.0;          // geometric: mean before the cut [samples]
  double loss = 0.0;                 // long-run share of lost packets, [0, 1)
  double burst = 1.0;                // mean length of a run of losses [samples], >= 1 (1: independent)

  AURORA_HD long maxLatency() const { return delay + (jitter == JitterKind::kNone ? 0 : jitter_max); }
  // No jitter and no loss: the packet of step j arrives at j + delay.
  AURORA_HD bool constant() const { return jitter == JitterKind::kNone && loss == 0.0; }
};

// A link: uplink (state to controller), downlink (command to drone).
struct LinkParams {
  LinkDirection uplink, downlink;
  uint32_t seed = 0;
  double cmd_timeout = 0.2;  // [s] the drone hovers when no new command arrived for this long

  // Today's loop: a constant uplink delay, nothing else.
  AURORA_HD bool ideal() const { return uplink.constant() && downlink.constant() && downlink.delay == 0; }

  // The history a run needs over this link with the uplink's base delay
  // `uplink_delay` (the run's delay replaces the link's own): its latest
  // state packet, or its latest command.
  AURORA_HD long historyNeeded(long uplink_delay) const {
    LinkDirection up = uplink;
    up.delay = uplink_delay;
    const long down = downlink.maxLatency();
    return up.maxLatency() > down ? up.maxLatency() : down;
  }
};

inline bool operator==(const LinkDirection& a, const LinkDirection& b) {
  return a.delay == b.delay && a.jitter == b.jitter && a.jitter_max == b.jitter_max &&
         a.jitter_mean == b.jitter_mean && a.loss == b.loss && a.burst == b.burst;
}
inline bool operator==(const LinkParams& a, const LinkParams& b) {
  return a.uplink == b.uplink && a.downlink == b.downlink && a.seed == b.seed && a.cmd_timeout == b.cmd_timeout;
}
inline bool operator!=(const LinkParams& a, const LinkParams& b) { return !(a == b); }

// The link's values a sweep varies and a live setting changes, in the
// parameter table's row order (kRowUplinkJitter on): a jitter is its max
// [samples] (the link's kind; uniform when it has none), the downlink's
// delay [samples], a loss, a burst. One rule for the sweep's combinations
// (host and device) and the node's live changes.
enum LinkValue : int {
  kLinkUplinkJitter,
  kLinkUplinkLoss,
  kLinkUplinkBurst,
  kLinkDownlinkDelay,
  kLinkDownlinkJitter,
  kLinkDownlinkLoss,
  kLinkDownlinkBurst,
  kLinkValueCount
};

AURORA_HD inline void setLinkValue(LinkParams& l, int which, double v) {
  LinkDirection& d = which < kLinkDownlinkDelay ? l.uplink : l.downlink;
  switch (which) {
    case kLinkUplinkJitter:
    case kLinkDownlinkJitter:
      d.jitter_max = static_cast<long>(v);
      if (d.jitter == JitterKind::kNone && d.jitter_max > 0) d.jitter = JitterKind::kUniform;
      break;
    case kLinkDownlinkDelay: d.delay = static_cast<long>(v); break;
    case kLinkUplinkLoss:
    case kLinkDownlinkLoss: d.loss = v; break;
    default: d.burst = v; break;
  }
}

AURORA_HD inline double linkValueOf(const LinkParams& l, int which) {
  const LinkDirection& d = which < kLinkDownlinkDelay ? l.uplink : l.downlink;
  switch (which) {
    case kLinkUplinkJitter:
    case kLinkDownlinkJitter: return double(d.jitter_max);
    case kLinkDownlinkDelay: return double(d.delay);
    case kLinkUplinkLoss:
    case kLinkDownlinkLoss: return d.loss;
    default: return d.burst;
  }
}

// A jitter kind's name in link files and logs.
inline const char* jitterKindName(JitterKind k) {
  return k == JitterKind::kUniform ? "uniform" : k == JitterKind::kGeometric ? "geometric" : "none";
}

AURORA_HD inline double unitFromBits(uint32_t x) {
  return (double(x) + 0.5) * (1.0 / 4294967296.0);  // in (0, 1), never 0 or 1
}

// The draws of one packet: two 32-bit words, for its jitter and its loss;
// as uniforms in (0, 1), u = (w + 1/2) / 2^32.
struct PacketDraws {
  uint32_t jitter_w, loss_w;
  AURORA_HD double jitterU() const { return unitFromBits(jitter_w); }
  AURORA_HD double lossU() const { return unitFromBits(loss_w); }
};

// The draws of step `step` on both directions (docs/links.md, "The draws"):
// one Philox4x32-10 block, key (seed, combination's low 32 bits), counter
// (step's low and high 32 bits, combination's high 32 bits, 0); its words 0
// and 1 are the uplink packet's jitter and loss draws, 2 and 3 the
// downlink packet's. One block per step: a run draws half as many as with a
// block per packet.
struct StepDraws {
  PacketDraws uplink, downlink;
  AURORA_HD const PacketDraws& of(LinkDirectionId dir) const {
    return dir == LinkDirectionId::kUplink ? uplink : downlink;
  }
};

// The block's key and counter of step `step`: the draws' key layout, for
// every backend (stepDraws here; the SIMD engine's lanes, lane_links.h).
// The key and the counter's last two words are the same at every step;
// only the step's two words (stepLow, stepHigh) change.
struct DrawBlock {
  uint32_t key[2], ctr[4];
  AURORA_HD static uint32_t stepLow(uint64_t step) { return static_cast<uint32_t>(step); }
  AURORA_HD static uint32_t stepHigh(uint64_t step) { return static_cast<uint32_t>(step >> 32); }
};
AURORA_HD inline DrawBlock drawBlock(uint32_t seed, uint64_t combination, uint64_t step) {
  return DrawBlock{{seed, static_cast<uint32_t>(combination)},
                   {DrawBlock::stepLow(step), DrawBlock::stepHigh(step), static_cast<uint32_t>(combination >> 32), 0u}};
}

AURORA_HD inline StepDraws stepDraws(uint32_t seed, uint64_t combination, uint64_t step) {
  r123::Philox4x32 philox;
  const DrawBlock b = drawBlock(seed, combination, step);
  const r123::Philox4x32::key_type key = {{b.key[0], b.key[1]}};
  const r123::Philox4x32::ctr_type ctr = {{b.ctr[0], b.ctr[1], b.ctr[2], b.ctr[3]}};
  const r123::Philox4x32::ctr_type r = philox(ctr, key);
  return StepDraws{PacketDraws{r.v[0], r.v[1]}, PacketDraws{r.v[2], r.v[3]}};
}

AURORA_HD inline PacketDraws packetDraws(uint32_t seed, uint64_t combination, LinkDirectionId dir, uint64_t step) {
  return stepDraws(seed, combination, step).of(dir);
}

// A packet's jitter [samples] from its uniform draw u (docs/links.md,
// "Jitter"): uniform, floor(u (max + 1)); geometric with mean m,
// floor(ln(1 - u) / ln(m / (1 + m))), cut at max. The channels use the
// exact integer form of the uniform one (jitterOfWord); this is the
// documented formula.
AURORA_HD inline long jitterSamples(const LinkDirection& d, double u) {
  if (d.jitter == JitterKind::kUniform) {
    const long j = static_cast<long>(u * double(d.jitter_max + 1));
    return j > d.jitter_max ? d.jitter_max : j;
  }
  if (d.jitter == JitterKind::kGeometric && d.jitter_mean > 0.0) {
    const double j = std::floor(std::log(1.0 - u) / std::log(d.jitter_mean / (1.0 + d.jitter_mean)));
    return j > double(d.jitter_max) ? d.jitter_max : static_cast<long>(j);
  }
  return 0;
}

// The uniform jitter of word w: floor(u (max + 1)) with u = (w + 1/2) / 2^32
// is floor((2w + 1)(max + 1) / 2^33), exactly (the product of doubles is
// exact: 34 bits times at most 12). Integer arithmetic only, so SIMD lanes
// compute it too.
AURORA_HD inline long uniformJitter(uint32_t w, long max) {
  return static_cast<long>(((2 * static_cast<uint64_t>(w) + 1) * static_cast<uint64_t>(max + 1)) >> 33);
}

AURORA_HD inline long jitterOfWord(const LinkDirection& d, uint32_t w) {
  return d.jitter == JitterKind::kUniform ? uniformJitter(w, d.jitter_max) : jitterSamples(d, unitFromBits(w));
}

// The loss chain (docs/links.md, "Loss"): with burst 1 each packet is lost
// with probability `loss`, independently; above 1 a Gilbert-Elliott chain
// whose bad state loses every packet: leave it with r = 1 / burst, enter it
// with q = loss r / (1 - loss), so that the long-run share lost is `loss`.
// Returns whether the packet of this step is lost, given whether the
// previous one was (the chain's state). The documented formula; the
// channels use its integer form (LossRule).
AURORA_HD inline bool packetLost(const LinkDirection& d, bool previous_lost, double u) {
  if (d.loss <= 0.0) return false;
  if (d.burst <= 1.0) return u < d.loss;
  const double r = 1.0 / d.burst;
  const double q = d.loss * r / (1.0 - d.loss);
  return previous_lost ? !(u < r) : u < q;
}

// How many words w have (w + 1/2) / 2^32 < p: u < p is w < wordsBelow(p),
// exactly (p 2^32 - 1/2 is exact in double for p < 1).
AURORA_HD inline uint64_t wordsBelow(double p) {
  if (!(p > 0.0)) return 0;
  const double t = std::ceil(p * 4294967296.0 - 0.5);
  return t >= 4294967296.0 ? 4294967296ull : static_cast<uint64_t>(t);
}

// packetLost on words, written once for one run (LossRule, LinkChannel)
// and for SIMD lanes (the sweep's LaneChannel, on arrays of each): after a
// packet that arrived (the good state) the next is lost when w < good; after
// a lost one (the bad state) when w < bad, and for the chain (flips 1) that
// test is flipped: it stays bad unless the word says it leaves. Independent
// losses: good = bad, flips 0. Branch-free integers (0 or 1), so the lanes'
// loop vectorizes.
AURORA_HD inline uint64_t lossStep(uint64_t previous_lost, uint64_t w, uint64_t good, uint64_t bad, uint64_t flips) {
  return uint64_t(w < (previous_lost ? bad : good)) ^ (previous_lost & flips);
}

// One packet sent, after the loss step (same callers): the packet of step k
// arrives at step k + delay + jitter, or never (-1) when lost.
template <typename Int>
AURORA_HD inline Int packetArrival(uint64_t lost, Int k, Int delay, Int jitter) {
  return lost ? Int(-1) : Int(k + delay + jitter);
}

// A condition as an integer mask (all ones: true), the form SIMD lanes
// compute conditions in (xsimd 8.1 builds some integer comparisons element by
// element); on one run's long it is the same arithmetic. a >= b is the sign
// of a - b (steps and delays are far from the integers' range). Int: the
// integers' type (a batch's element type).
template <typename Int, typename I>
AURORA_HD inline I atLeastMask(const I& a, const I& b) {
  return ~((a - b) >> (8 * sizeof(Int) - 1));
}

// The drone's watchdog, written once for one run (ModelLink) and for SIMD
// lanes (the sweep's LaneLinks): it hovers when no command has arrived
// (newest < 0) or the newest arrived `timeout` steps ago or more (`since`).
template <typename Int, typename I>
AURORA_HD inline I hoverMask(const I& newest, const I& since, const I& timeout) {
  return ~atLeastMask<Int>(newest, I(Int(0))) | atLeastMask<Int>(since, timeout);
}

// lossStep's thresholds of a direction, computed once. (`flips` a bool, not
// a word: the kernels keep one register and several spills fewer.)
struct LossRule {
  uint64_t good;   // independent losses: lost when w < good; the chain: enter the bad state when w < good
  uint64_t bad;    // the chain: leave the bad state when w < bad
  bool flips;      // the Gilbert-Elliott chain (burst > 1)

  AURORA_HD static LossRule of(const LinkDirection& d) {
    LossRule rule{0, 0, false};
    if (d.loss <= 0.0) return rule;
    if (d.burst <= 1.0) {
      rule.good = rule.bad = wordsBelow(d.loss);
      return rule;
    }
    const double r = 1.0 / d.burst;
    rule.flips = true;
    rule.bad = wordsBelow(r);
    rule.good = wordsBelow(d.loss * r / (1.0 - d.loss));
    return rule;
  }
  AURORA_HD bool lost(bool previous_lost, uint32_t w) const {
    return lossStep(previous_lost, w, good, bad, flips ? 1 : 0) != 0;
  }
};

// One direction of a link, from its sender's step to its receiver's choice.
// Window: how many recent packets it tracks; a link's maxLatency() must be
// below it (checked by the caller: linkRefusal).
template <int Window>
class LinkChannel {
 public:
  static constexpr long kNever = -1;

  AURORA_HD LinkChannel() { reset(); }

  AURORA_HD void reset() {
    newest_ = -1;
    newest_arrival_step_ = -1;
    lost_ = false;
    losses_ = 0;
  }

  // Sends the packet of step k (k = 0, 1, ... in order) with its draws u
  // and d's loss rule (LossRule::of(d), computed once by the caller):
  // whether it is lost and when it arrives.
  AURORA_HD void send(const LinkDirection& d, const LossRule& rule, const PacketDraws& u, long k) {
    if (d.constant()) {
      arrival_[k % Window] = k + d.delay;
      return;
    }
    lost_ = rule.lost(lost_, u.loss_w);
    losses_ += lost_ ? 1 : 0;
    arrival_[k % Window] = packetArrival<long>(lost_, k, d.delay, jitterOfWord(d, u.jitter_w));
  }

  // At step k (after send(k)): the step of the newest-sent packet that has
  // arrived by k, or -1 while none has. A packet older than one already
  // received is ignored when it arrives (receivers check sequence numbers).
  AURORA_HD long receive(const LinkDirection& d, long k) {
    // Packets sent after k - delay cannot have arrived; before k - maxLatency
    // all that will arrive have.
    const long oldest = k - d.maxLatency();
    for (long j = k - d.delay; j >= (oldest > 0 ? oldest : 0) && j > newest_; --j) {
      const long at = arrival_[j % Window];
      if (at != kNever && at <= k) {
        newest_ = j;
        newest_arrival_step_ = k;
        break;
      }
    }
    return newest_;
  }

  // No packet was sent at step k (a state the node never received, a step
  // without a command): it never arrives; the loss chain does not advance.
  AURORA_HD void miss(long k) { arrival_[k % Window] = kNever; }

  // Steps since a newer packet last arrived (receive), or -1 if none has.
  AURORA_HD long sinceArrival(long k) const { return newest_ < 0 ? -1 : k - newest_arrival_step_; }
  // The step the newest packet received was sent at, or -1.
  AURORA_HD long newest() const { return newest_; }
  AURORA_HD long losses() const { return losses_; }

 private:
  long arrival_[Window];
  long newest_;
  long newest_arrival_step_;
  bool lost_;
  long losses_;
};

}  // namespace aurora_control
