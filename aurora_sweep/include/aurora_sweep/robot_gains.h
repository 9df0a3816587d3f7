// A formation robot's own law's gains as sweep parameters (docs/formation.md,
// "Formation sweeps"): robot r's block of kRobotGainRoom values from
// robotGainParam(r, 0) (combination.h), named by its law's gains with the
// robot's number (k1_x_2, kc1_1, kp_1). RobotGains<Law> says, for a law
// type, which gains a block holds for a robot of given parameters (its
// rows, host) and puts a combination's block into the robot's gains (host
// and device: the scalar loop, the SIMD lanes and the CUDA thread all build
// a combination's run with formationCombination). A value the sweep does
// not give is NaN and leaves the formation file's gain as it is.
#pragma once

#include <vector>

#include "aurora_common/host_device.h"
#include "aurora_control/law/either_law.h"
#include "aurora_control/law/law_gain_rows.h"
#include "aurora_control/params/limits.h"
#include "aurora_sweep/sweep_gains.h"

namespace aurora_sweep {

// Every law of the list: the rows its own declaration gives
// (law_gain_rows.h), its block.
template <class Law>
struct RobotGains {
  static_assert(Law::kGainCount <= kRobotGainRoom, "a robot's law whose gains exceed a robot's block");
  template <class Params>
  static const char* law(const Params&) {
    return Law::name();
  }
  template <class Params>
  static std::vector<LawGainRow> rows(const Params&) {
    std::vector<LawGainRow> r;
    for (int i = 0; i < Law::kGainCount; ++i) r.push_back(Law::gainRow(i));
    return r;
  }
  template <class Gains, class Params>
  AURORA_HD static void set(Gains& g, const Params&, const double* v) {
    Law::giveGains(g, v);
  }
};
// A mixed crew's robot: the law its parameters choose.
template <class First, class Second>
struct RobotGains<aurora_control::EitherLaw<First, Second>> {
  template <class Params>
  static const char* law(const Params& p) {
    return p.is_second ? RobotGains<Second>::law(p.second) : RobotGains<First>::law(p.first);
  }
  template <class Params>
  static std::vector<LawGainRow> rows(const Params& p) {
    return p.is_second ? RobotGains<Second>::rows(p.second) : RobotGains<First>::rows(p.first);
  }
  template <class Gains, class Params>
  AURORA_HD static void set(Gains& g, const Params& p, const double* v) {
    if (p.is_second) RobotGains<Second>::set(g.second, p.second, v);
    else RobotGains<First>::set(g.first, p.first, v);
  }
};

}  // namespace aurora_sweep
