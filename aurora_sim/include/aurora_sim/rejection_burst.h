// Logging of rejected input (NaN/Inf commands) without flooding the log:
// one warning when a burst starts, a summary line every `summary_period`
// while it lasts, one line when it ends. A burst ends only after
// `quiet_period` without a rejection: valid commands from another publisher
// interleaved with the bad ones (a controller still running) do not end it.
// ROS-free: the node passes the time in, calls `poll` first on each input
// and on its timer, and logs what the calls return.
#pragma once

namespace aurora_sim {

struct BurstReport {
  enum Kind { kNone, kStarted, kSummary, kEnded };
  Kind kind = kNone;
  unsigned long rejected = 0;  // kSummary: since the last line; kEnded: whole burst
  unsigned long accepted = 0;  // valid inputs between them (same span)
  double span = 0.0;           // [s] covered by the counts
};

class RejectionBurst {
 public:
  RejectionBurst(double quiet_period = 1.0, double summary_period = 5.0)
      : quiet_(quiet_period), summary_period_(summary_period) {}

  bool active() const { return active_; }

  // An input was rejected at time t [s]; kStarted when a burst begins.
  BurstReport rejected(double t) {
    BurstReport r;
    last_rejected_ = t;
    ++window_rejected_;
    ++total_rejected_;
    if (active_) return r;
    active_ = true;
    started_ = window_start_ = t;
    window_rejected_ = total_rejected_ = 1;
    window_accepted_ = total_accepted_ = 0;
    r.kind = BurstReport::kStarted;
    return r;
  }

  // A valid input: counted while a burst lasts.
  void accepted() {
    if (active_) ++window_accepted_, ++total_accepted_;
  }

  // Time passes (a timer): kEnded once quiet for quiet_period, kSummary every
  // summary_period while the burst lasts.
  BurstReport poll(double t) {
    BurstReport r;
    if (!active_) return r;
    if (t - last_rejected_ >= quiet_) {
      active_ = false;
      r.kind = BurstReport::kEnded;
      r.rejected = total_rejected_;
      r.accepted = total_accepted_;
      r.span = last_rejected_ - started_;
      return r;
    }
    if (t - window_start_ >= summary_period_) {
      // A window with no rejection (the quiet tail) has nothing to say.
      if (window_rejected_ > 0) r.kind = BurstReport::kSummary;
      r.rejected = window_rejected_;
      r.accepted = window_accepted_;
      r.span = t - window_start_;
      window_start_ = t;
      window_rejected_ = window_accepted_ = 0;
    }
    return r;
  }

 private:
  double quiet_, summary_period_;
  bool active_ = false;
  double started_ = 0.0, last_rejected_ = 0.0, window_start_ = 0.0;
  unsigned long window_rejected_ = 0, window_accepted_ = 0;
  unsigned long total_rejected_ = 0, total_accepted_ = 0;
};

}  // namespace aurora_sim
