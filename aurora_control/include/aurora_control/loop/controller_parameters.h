// The controller's parameters, each declared once where it belongs
// (docs/architecture.md, "The parameter table"): the loop's and the nodes'
// rows (params/parameter_table.h), after the gains of each law whose gains
// are its rows (its gainRow, law_gain_rows.h: the laws the node changes
// live), in the laws' list order. docs/parameters.md's controller reference
// is controllerParameterReference(), and Controller.cfg's live settings are
// the rows with a live name (src/controller_live_settings_main.cpp prints
// them at build time): a law added to the list reaches both with no edit.
#pragma once

#include <deque>
#include <iterator>
#include <string>
#include <vector>

#include "aurora_control/loop/law_yaml.h"
#include "aurora_control/params/parameter_table.h"

namespace aurora_control {

// Calls f(Law()) for each law of the list whose gains are its rows
// (gainsAreRows: the gains the reconfigure server shows).
template <class F>
void forEachLiveGainLaw(F&& f) {
  forEachLaw([&](auto law) {
    if (gainsAreRows<decltype(law)>()) f(law);
  });
}

namespace controller_parameters_detail {

// A law's gain row as a parameter row: its live setting is its name.
inline ParameterSpec gainParameter(const GainRow& g, const char* doc) {
  return {g.name, g.whole ? ParamKind::kWhole : ParamKind::kReal, g.preset, g.min, g.max, "", doc, nullptr, g.name,
          false, nullptr};
}

// The rows, built once; `docs` holds the texts the rows point to.
struct ControllerRows {
  std::deque<std::string> docs;
  std::vector<ParameterSpec> rows;
  ControllerRows() {
    forEachLiveGainLaw([&](auto law) {
      using Law = decltype(law);
      for (int i = 0; i < Law::kGainCount; ++i) {
        const GainRow g = Law::gainRow(i);
        docs.push_back(std::string(Law::name()) + " law: " + (g.meaning ? g.meaning : std::string("gain ") + g.name));
        rows.push_back(gainParameter(g, docs.back().c_str()));
      }
    });
    rows.insert(rows.end(), std::begin(kParameterTable), std::end(kParameterTable));
  }
};

}  // namespace controller_parameters_detail

// Every parameter of the controller: the live laws' gains, then the table.
inline const std::vector<ParameterSpec>& controllerParameters() {
  static const controller_parameters_detail::ControllerRows all;
  return all.rows;
}

// The controller's parameter with live setting `live` (a gain's is its
// name), or nullptr.
inline const ParameterSpec* controllerLiveSetting(const std::string& live) {
  return rowWithLiveName(controllerParameters(), live);
}

// The parameters as docs/parameters.md's markdown (between its markers).
inline std::string controllerParameterReference() { return aurora_common::parameterReference(controllerParameters()); }

}  // namespace aurora_control
