// How a combination's values set the gains of each law a sweep flies
// (docs/delay-and-study.md, "Sweeping any parameter"): SweepGains<Data>
// names the sweep parameters a law family reads (host and device). The
// AR.Drone's laws read kp, kd and the underactuated law's 12 gains; every
// other law reads its own block, which it declares in its own header
// (law_gain_rows.h: its rows' names, defaults, ranges, and how a block sets
// its gains) and LawGainBlock places (combination.h); the parameter table
// (parameters.cpp), the record and the hash follow. The vehicles' laws
// take x and y as one gain (AuRoRA's are equal on x and y; a controller file
// may still set them apart for a flight).
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_control/law/control_law.h"
#include "aurora_control/law/law_gain_rows.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_sweep/combination.h"

namespace aurora_sweep {

using aurora_control::giveGain;
using LawGainRow = aurora_control::GainRow;

// Every other law (the laws' list, other_laws.h): the block its own
// declaration names (law_gain_rows.h) where LawGainBlock places it; the
// rest of its gains its defaults().
template <class Law>
struct SweepGains {
  template <typename T>
  AURORA_HD static typename Law::template Gains<T> from(const Combination& c) {
    auto g = Law::template Gains<T>::defaults();
    Law::giveGains(g, c.v + LawGainBlock<Law>::kFirst);
    return g;
  }
};

// The AR.Drone's laws: the PD law's kp, kd; the underactuated law's 12
// gains (underactuatedGainName order).
template <>
struct SweepGains<aurora_control::ArdroneLawData> {
  template <typename T>
  AURORA_HD static aurora_control::LawGains<T> from(const Combination& c) {
    aurora_control::LawGains<T> g;
    g.pd.kp = T(c.v[kParamKp]);
    g.pd.kd = T(c.v[kParamKd]);
    for (int i = 0; i < kUnderactuatedGainCount; ++i) {
      aurora_control::underactuatedGain(g.underactuated, i) = T(c.v[kParamFirstUnderactuatedGain + i]);
    }
    return g;
  }
};

// f(id) for each parameter of the laws' own gains, law by law in the list's
// order (each block's rows in order).
template <class F>
void forEachLawGainParam(F&& f) {
  aurora_control::forEachOtherLaw([&](auto law) {
    using Block = LawGainBlock<decltype(law)>;
    for (int i = 0; i < Block::kCount; ++i) f(Block::kFirst + i);
  });
}

// The laws a sweep flies besides the AR.Drone's (law/other_laws.h).
using aurora_control::forEachOtherLaw;

}  // namespace aurora_sweep
