#include "aurora_sweep/parameters.h"

#include <limits>

#include "aurora_control/limits.h"
#include "aurora_control/link.h"
#include "aurora_control/parameter_table.h"
#include "aurora_control/underactuated_law.h"

namespace aurora_sweep {

namespace {

// Model factors: a positive multiple of the identified value, at most 10x
// either way (beyond that the identified motor and on-board models no
// longer describe a drone of this kind).
constexpr double kFactorMin = 0.1, kFactorMax = 10.0;

std::vector<ParamInfo> makeTable() {
  using namespace aurora_control;
  std::vector<ParamInfo> t(kParamCount);
  const std::string pd = "the controller node's PD gain range";
  t[kParamKp] = {"kp", ParamGroup::kPdGain, kPdGainMin, kPdGainMax, pd};
  t[kParamKd] = {"kd", ParamGroup::kPdGain, kPdGainMin, kPdGainMax, pd};
  t[kParamDelay] = {"delay", ParamGroup::kDelay, 0.0, double(kMaxDelaySamples),
                    "whole samples of Ts, the histories' limit", true};
  for (int i = 0; i < kUnderactuatedGainCount; ++i) {
    t[kParamFirstUnderactuatedGain + i] = {underactuatedGainName(i), ParamGroup::kUnderactuatedGain,
                                           kUnderactuatedGainMin, kUnderactuatedGainMax,
                                           "the controller node's underactuated gain range (positive)"};
  }
  const char* model[kModelFactorCount] = {"m", "Ixx", "Iyy", "Izz", "Cf", "Ct", "Km", "Jm"};
  for (int i = 0; i < kModelFactorCount; ++i) {
    t[kParamFirstModelFactor + i] = {model[i], ParamGroup::kModelFactor, kFactorMin, kFactorMax,
                                     "a factor of the vehicle file's value: positive, at most 10x either way"};
  }
  // The link's values: the parameter table's rows (their live names, ranges).
  for (int i = 0; i < kLinkParamCount; ++i) {
    const ParameterSpec& row = kParameterTable[kRowUplinkJitter + i];
    t[kParamFirstLinkValue + i] = {row.live, ParamGroup::kLink, row.min, row.max,
                                   std::string(row.doc) + (row.unit[0] ? std::string(", ") + row.unit : ""),
                                   row.kind == ParamKind::kWholeSamples};
  }
  t[kParamRepeat] = {"repeat", ParamGroup::kRepeat, 0.0, 1e9, "which link seed (sweep.repeats)", true};
  return t;
}

}  // namespace

const ParamInfo& paramInfo(int id) {
  static const std::vector<ParamInfo> table = makeTable();
  return table[static_cast<size_t>(id)];
}

int paramIdOf(const std::string& name) {
  for (int id = 0; id < kParamCount; ++id) {
    if (paramInfo(id).name == name) return id;
  }
  return -1;
}

bool paramApplies(int id, aurora_control::LawType law) {
  switch (paramInfo(id).group) {
    case ParamGroup::kPdGain: return law == aurora_control::LawType::kPdSaturated;
    case ParamGroup::kUnderactuatedGain: return law == aurora_control::LawType::kUnderactuated;
    case ParamGroup::kRepeat: return false;  // sweep.repeats, not a parameter
    default: return true;
  }
}

std::string acceptedParamNames(aurora_control::LawType law) {
  std::string names;
  for (int id = 0; id < kParamCount; ++id) {
    if (paramApplies(id, law)) names += (names.empty() ? "" : ", ") + paramInfo(id).name;
  }
  return names;
}

bool lawFromName(const std::string& name, aurora_control::LawType& law) {
  if (name == "pd_saturated") law = aurora_control::LawType::kPdSaturated;
  else if (name == "underactuated") law = aurora_control::LawType::kUnderactuated;
  else return false;
  return true;
}

const char* lawName(aurora_control::LawType law) {
  return law == aurora_control::LawType::kPdSaturated ? "pd_saturated" : "underactuated";
}

double paramDefault(int id) {
  switch (paramInfo(id).group) {
    case ParamGroup::kUnderactuatedGain: {
      const auto g = aurora_control::UnderactuatedGains<double>::defaults();
      return aurora_control::underactuatedGain(g, id - kParamFirstUnderactuatedGain);
    }
    case ParamGroup::kModelFactor: return 1.0;
    case ParamGroup::kLink: return aurora_control::linkValueOf(aurora_control::LinkParams(), id - kParamFirstLinkValue);
    case ParamGroup::kRepeat: return 0.0;
    default: return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace aurora_sweep
