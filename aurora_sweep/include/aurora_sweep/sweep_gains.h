// How a combination's values set the gains of each law a sweep flies
// (docs/delay-and-study.md, "Sweeping any parameter"): SweepGains<Data>
// names the sweep parameters a law family reads (host and device): every
// law reads its own block, which it declares in its own header
// (law_gain_rows.h: its rows' names, defaults, ranges, and how a block sets
// its gains) and LawGainBlock places (combination.h); the parameter table
// (parameters.cpp), the record and the hash follow. The vehicles' laws
// take x and y as one gain (AuRoRA's are equal on x and y; a controller file
// may still set them apart for a flight).
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_control/law/law_gain_rows.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_sweep/combination.h"

namespace aurora_sweep {

using aurora_control::giveGain;
using LawGainRow = aurora_control::GainRow;

namespace sweep_gains_detail {
// Each law of the list that shares `Data` gives its block into the gains
// (laws that share a Data share one gains struct: each law's block sets
// its own part of it).
template <class Data, class List>
struct GiveShared;
template <class Data>
struct GiveShared<Data, aurora_common::TypeList<>> {
  static constexpr bool kAny = false;  // whether a law of the list flies Data
  template <class Gains>
  AURORA_HD static void give(Gains&, const Combination&) {}
};
template <class Data, class Law, class... Rest>
struct GiveShared<Data, aurora_common::TypeList<Law, Rest...>> {
  static constexpr bool kAny =
      std::is_same<typename Law::Data, Data>::value || GiveShared<Data, aurora_common::TypeList<Rest...>>::kAny;
  template <class Gains>
  AURORA_HD static void give(Gains& g, const Combination& c) {
    giveIf(std::is_same<typename Law::Data, Data>(), g, c);
    GiveShared<Data, aurora_common::TypeList<Rest...>>::give(g, c);
  }
  template <class Gains>
  AURORA_HD static void giveIf(std::true_type, Gains& g, const Combination& c) {
    Law::giveGains(g, c.v + LawGainBlock<Law>::kFirst);
  }
  template <class Gains>
  AURORA_HD static void giveIf(std::false_type, Gains&, const Combination&) {}
};
}  // namespace sweep_gains_detail

// A law family's gains from a combination (Data: a law's data, which the
// laws chosen among at run time share): its defaults(), then the block of
// each law of the list flying it where LawGainBlock places it.
template <class Data>
struct SweepGains {
  using Laws = sweep_gains_detail::GiveShared<Data, aurora_control::KnownLaws>;
  static_assert(Laws::kAny, "the data of a law of the laws' list (other_laws.h)");
  template <typename T>
  AURORA_HD static typename Data::template Gains<T> from(const Combination& c) {
    auto g = Data::template Gains<T>::defaults();
    Laws::give(g, c);
    return g;
  }
};

// f(id) for each parameter of the laws' own gains, law by law in the list's
// order (each block's rows in order).
template <class F>
void forEachLawGainParam(F&& f) {
  aurora_control::forEachLaw([&](auto law) {
    using Block = LawGainBlock<decltype(law)>;
    for (int i = 0; i < Block::kCount; ++i) f(Block::kFirst + i);
  });
}

}  // namespace aurora_sweep
