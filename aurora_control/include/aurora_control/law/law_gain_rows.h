// What a law declares of the gains a sweep may vary (docs/architecture.md,
// "Laws"; docs/delay-and-study.md, "Sweeping any parameter"): each law
// listed in other_laws.h gives, in its own header,
//
//   static constexpr int kGainCount;          // its sweep parameters
//   static GainRow gainRow(int i);            // name, default, range (host)
//   template <typename T> AURORA_HD
//   static void giveGains(Gains<T>& g, const double* v);  // a block into g
//
// (the AR.Drone's two: PdGainRows, UnderactuatedGainRows beside their
// laws), and, where every gain of the law is one of its rows,
//
//   static double& gainAt(Gains<double>& g, int i);  // row i's gain in g
//
// (the AR.Drone's two: loop/law_yaml.h then reads its controller file by
// its rows, and the controller node changes them live); the sweep places the block (aurora_sweep/sweep_gains.h), names its
// rows in the parameter table, records them and hashes them: nothing of a
// law's gains is written outside its own files.
#pragma once

#include "aurora_common/host_device.h"

namespace aurora_control {

// One gain a sweep may vary: its name, its default (the law's defaults();
// NaN: none, a sweep of the law names it), its accepted range, whole values
// only, what the range is (a refusal says it; null: the range of the
// law's controller file), and what the gain does (the controller node's
// parameter reference and live setting, for a law whose gains are its rows;
// null: "gain NAME").
struct GainRow {
  const char* name;
  double preset, min, max;
  bool whole;
  const char* range = nullptr;
  const char* meaning = nullptr;
};

// A swept value into a gain; NaN (a formation sweep's robot gain it does
// not give) keeps the gain's value.
template <typename T>
AURORA_HD inline void giveGain(T& gain, double v) {
  if (v == v) gain = T(v);
}

}  // namespace aurora_control
