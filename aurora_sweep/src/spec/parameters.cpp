#include "aurora_sweep/parameters.h"

#include <limits>

#include <boost/algorithm/string.hpp>

#include "aurora_control/formation/formation_layer.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/link/link.h"
#include "aurora_control/params/parameter_table.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "aurora_sweep/sweep_gains.h"

namespace aurora_sweep {

namespace {

// Model factors: a positive multiple of the identified value, at most 10x
// either way (beyond that the identified motor and on-board models no
// longer describe a drone of this kind).
constexpr double kFactorMin = 0.1, kFactorMax = 10.0;

// A formation's parameters where shapeLayout puts them (combination.h):
// each robot's delay, the shape's gains by its variables' names, each
// robot's own link values (the link values' rows, suffixed _1 ... _N).
template <class Shape>
void addShapeParams(std::vector<ParamInfo>& t) {
  using namespace aurora_control;
  constexpr ShapeLayout at = shapeLayout<Shape>();
  for (int d = 0; d < at.robots; ++d) {
    t[at.delay(d)] = {"delay_" + std::to_string(d + 1), ParamGroup::kDroneDelay, 0.0, double(kMaxDelaySamples),
                      "whole samples of Ts, the histories' limit", true};
  }
  for (int i = 0; i < at.variables; ++i) {
    const std::string limit = "a formation gain: positive, the formation layer's range";
    t[at.k1(i)] = {std::string("formation_k1_") + Shape::gainName(i), ParamGroup::kFormationGain,
                   kFormationGainMin, kFormationGainMax, limit};
    t[at.k2(i)] = {std::string("formation_k2_") + Shape::gainName(i), ParamGroup::kFormationGain,
                   kFormationGainMin, kFormationGainMax, limit};
  }
  for (int d = 0; d < at.robots; ++d) {
    for (int i = 0; i < kLinkParamCount; ++i) {
      ParamInfo info = t[kParamFirstLinkValue + i];
      info.name += "_" + std::to_string(d + 1);
      info.group = ParamGroup::kDroneLink;
      t[at.linkValue(d, i)] = info;
    }
  }
}

// Law `Law`'s own gains (its declaration's rows) where its block is.
template <class Law>
void addLawGains(std::vector<ParamInfo>& t) {
  using Block = LawGainBlock<Law>;
  for (int i = 0; i < Block::kCount; ++i) {
    const LawGainRow row = Law::gainRow(i);
    const std::string limit = row.range ? row.range
                              : row.whole ? "whole model steps between the law's runs (1: every step)"
                                          : "the range of the law's controller file";
    ParamInfo info{row.name, ParamGroup::kLawGain, row.min, row.max, limit, row.whole, Law::name(), row.preset};
    t[Block::kFirst + i] = info;
  }
}

// f(Shape()) with the shape whose parameters a sweep of `shape` names (its
// entry's ParamShape; single-robot sweeps: the first shape's, which none of
// them accepts).
template <class F>
void withParamShape(SweepShape shape, F&& f) {
  using First = aurora_common::FirstType<aurora_control::KnownShapes>::type;
  if (shape == SweepShape::kNone) return f(typename First::ParamShape());
  withSweepShape(shape, [&](auto e) { f(typename decltype(e)::ParamShape()); });
}

// The shape's parameters, and the laws its formation_law chooses (its
// entry's, if it has any).
void addShape(SweepShape shape, std::vector<ParamInfo>& t) {
  withParamShape(shape, [&](auto s) { addShapeParams<decltype(s)>(t); });
  withSweepShape(shape, [&](auto e) {
    using E = decltype(e);
    if (E::kSweepLaws == 0) return;
    t[kParamFormationLaw] = {"formation_law", ParamGroup::kFormationLaw, 0.0, double(E::kSweepLaws - 1),
                             std::string("the ") + E::name() + "'s law by name (" + E::sweepLawNames() +
                                 ") or its index 0 .. " + std::to_string(E::kSweepLaws - 1), true};
  });
}

// Vehicle V's model factors in the sweep's slots (V::factorName order;
// the slots it does not have unused).
template <class V>
std::vector<ParamInfo> factorRows() {
  std::vector<ParamInfo> rows(kModelFactorCount, ParamInfo{"", ParamGroup::kUnused, 0.0, 0.0, "", false});
  static_assert(V::kFactors <= kModelFactorCount, "the sweep holds kModelFactorCount model factors");
  for (int i = 0; i < V::kFactors; ++i) {
    rows[static_cast<size_t>(i)] = {V::factorName(i), ParamGroup::kModelFactor, kFactorMin, kFactorMax,
                                    "a factor of the vehicle file's value: positive, at most 10x either way"};
  }
  return rows;
}

std::vector<ParamInfo> makeTable(SweepShape shape) {
  using namespace aurora_control;
  // Room no shape of the sweep uses: no name, applies to no sweep.
  std::vector<ParamInfo> t(kParamCount, ParamInfo{"", ParamGroup::kUnused, 0.0, 0.0, "", false});
  t[kParamDelay] = {"delay", ParamGroup::kDelay, 0.0, double(kMaxDelaySamples),
                    "whole samples of Ts, the histories' limit", true};
  for (int i = 0; i < kModelFactorCount; ++i) {
    t[kParamFirstModelFactor + i] = modelFactorInfo(aurora_sim::DefaultVehicle::name(), i);
  }
  // The link's values: the parameter table's rows (their live names, ranges).
  for (int i = 0; i < kLinkParamCount; ++i) {
    const ParameterSpec& row = kParameterTable[kRowUplinkJitter + i];
    t[kParamFirstLinkValue + i] = {row.live, ParamGroup::kLink, row.min, row.max,
                                   std::string(row.doc) + (row.unit[0] ? std::string(", ") + row.unit : ""),
                                   row.kind == ParamKind::kWholeSamples};
  }
  t[kParamRepeat] = {"repeat", ParamGroup::kRepeat, 0.0, 1e9, "which link seed (sweep.repeats)", true};
  forEachLaw([&](auto law) { addLawGains<decltype(law)>(t); });
  addShape(shape, t);
  return t;
}

}  // namespace

const ParamInfo& modelFactorInfo(const std::string& vehicle_type, int i) {
  static const std::vector<std::pair<std::string, std::vector<ParamInfo>>> tables = [] {
    std::vector<std::pair<std::string, std::vector<ParamInfo>>> t;
    aurora_sim::forEachVehicle([&](auto v) { t.emplace_back(v.name(), factorRows<decltype(v)>()); });
    return t;
  }();
  for (const auto& t : tables) {
    if (t.first == vehicle_type) return t.second[static_cast<size_t>(i)];
  }
  return tables.front().second[static_cast<size_t>(i)];  // not reached: a sweep's vehicle type is known
}

const char* sweepShapeName(SweepShape shape) {
  const char* name = "none";
  withSweepShape(shape, [&](auto e) { name = e.name(); });
  return name;
}

std::vector<std::string> formationLawNames(SweepShape shape) {
  std::string names;
  withSweepShape(shape, [&](auto e) { names = decltype(e)::sweepLawNames(); });
  std::vector<std::string> laws;
  if (names.empty()) return laws;
  boost::algorithm::split(laws, names, boost::algorithm::is_any_of(","));
  for (std::string& law : laws) boost::algorithm::trim(law);
  return laws;
}

const ParamInfo& paramInfo(int id, SweepShape shape) {
  static const std::vector<std::vector<ParamInfo>> tables = [] {
    std::vector<std::vector<ParamInfo>> t;
    for (int s = 0; s < kSweepShapeCount; ++s) t.push_back(makeTable(static_cast<SweepShape>(s)));
    return t;
  }();
  return tables[static_cast<size_t>(shape)][static_cast<size_t>(id)];
}

bool paramApplies(const ParamInfo& info, const std::string& controller, SweepShape shape) {
  const ParamGroup group = info.group;
  if (shape != SweepShape::kNone) {
    return group == ParamGroup::kDroneDelay || group == ParamGroup::kFormationGain || group == ParamGroup::kLink ||
           group == ParamGroup::kDroneLink || group == ParamGroup::kFormationLaw || group == ParamGroup::kRobotGain;
  }
  switch (group) {
    case ParamGroup::kLawGain: return info.law == controller;
    case ParamGroup::kModelFactor: return true;  // the sweep's vehicle's (SweepSpec::param names them)
    case ParamGroup::kRepeat: return false;  // sweep.repeats, not a parameter
    case ParamGroup::kDroneDelay:
    case ParamGroup::kFormationGain:
    case ParamGroup::kDroneLink:
    case ParamGroup::kFormationLaw:
    case ParamGroup::kRobotGain: return false;  // a formation sweep's
    case ParamGroup::kUnused: return false;
    default: return true;
  }
}

double paramDefault(int id, SweepShape shape) {
  const ParamInfo& info = paramInfo(id, shape);
  switch (info.group) {
    case ParamGroup::kModelFactor: return 1.0;
    case ParamGroup::kLawGain: return info.preset;
    case ParamGroup::kLink: return aurora_control::linkValueOf(aurora_control::LinkParams(), id - kParamFirstLinkValue);
    case ParamGroup::kRepeat: return 0.0;
    case ParamGroup::kFormationGain: {
      double value = 0.0;
      withParamShape(shape, [&](auto s) {
        using Shape = decltype(s);
        constexpr ShapeLayout at = shapeLayout<Shape>();
        const auto g = aurora_control::FormationGains<double, at.variables>::template of<Shape>();
        const int i = id - at.k1(0);
        value = i < at.variables ? g.k1[i] : g.k2[i - at.variables];
      });
      return value;
    }
    case ParamGroup::kFormationLaw: return 0.0;  // N
    default: return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace aurora_sweep
