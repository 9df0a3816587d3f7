// A parameter table's row, and the table as its markdown reference: how a
// package writes its parameters once (docs/architecture.md, "The parameter
// table"). aurora_control's table holds the loop's and the controller
// node's rows (aurora_control/params/parameter_table.h), aurora_sim's the
// simulator node's (aurora_sim/sim_parameters.h); the nodes read every row
// through ros/params.h, and docs/parameters.md holds each table's
// reference (tests compare).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace aurora_common {

enum class ParamKind { kReal, kWholeSamples, kWhole, kBool, kWord, kText, kPoint };

struct ParameterSpec {
  const char* name;      // in the YAML files and ROS parameters (sweep files and reconfigure: see doc)
  ParamKind kind;
  double default_value;  // NaN: none, the file must give it (kBool: 0 or 1; kWord: the default's index)
  double min, max;       // accepted values, inclusive (NaN max: none, or see doc)
  const char* unit;      // "" for none
  const char* doc;
  const char* choices;   // kWord: the accepted words, '|'-separated; default_value is the default's index
  const char* live;      // its name as a live setting (dynamic_reconfigure, Controller.cfg), or none
  bool min_excluded;     // min itself is refused: (min, max]
  const char* text;      // kText, kPoint: the default as text (nullptr: none)
};

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

inline const char* paramKindName(ParamKind k) {
  switch (k) {
    case ParamKind::kReal: return "real";
    case ParamKind::kWholeSamples:
    case ParamKind::kWhole: return "whole";
    case ParamKind::kBool: return "bool";
    case ParamKind::kText: return "text";
    case ParamKind::kPoint: return "point";
    case ParamKind::kWord: break;
  }
  return "word";
}

// A word row's accepted words, in order.
inline std::vector<std::string> paramChoices(const ParameterSpec& p) {
  std::vector<std::string> words;
  const std::string all = p.choices ? p.choices : "";
  for (size_t a = 0; a <= all.size() && !all.empty();) {
    const size_t b = std::min(all.find('|', a), all.size());
    words.push_back(all.substr(a, b - a));
    a = b + 1;
  }
  return words;
}

// One value of the reference: "—" for none (or no upper limit), true/false
// for a flag, the word of a word row.
inline std::string referenceValue(const ParameterSpec& p, double v) {
  if (std::isnan(v) || v >= std::numeric_limits<double>::max()) return "—";
  if (p.kind == ParamKind::kBool) return v != 0.0 ? "true" : "false";
  if (p.kind == ParamKind::kWord) {
    const std::vector<std::string> words = paramChoices(p);
    return words[static_cast<size_t>(v)];
  }
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// One row of the reference.
inline std::string referenceRow(const ParameterSpec& p) {
  std::string lo = referenceValue(p, p.min), hi = referenceValue(p, p.max);
  if (p.min_excluded) lo = "above " + lo;
  if (p.kind == ParamKind::kWord) {  // the accepted words instead of a range
    lo = "one of ", hi = "—";
    for (const std::string& w : paramChoices(p)) lo += (lo.size() > 7 ? ", " : "") + w;
  }
  const bool texts = p.kind == ParamKind::kText || p.kind == ParamKind::kPoint;
  if (texts) lo = hi = "—";
  const std::string fallback = texts ? (p.text ? p.text : "—") : referenceValue(p, p.default_value);
  const std::string live = p.live ? std::string("`") + p.live + "`" : std::string("—");
  return std::string("| `") + p.name + "` | " + live + " | " + paramKindName(p.kind) + " | " + fallback + " | " +
         lo + " | " + hi + " | " + p.unit + " | " + p.doc + " |\n";
}

// A table (an array or a vector of rows) as docs/parameters.md's markdown
// (between its markers).
template <class Rows>
std::string parameterReference(const Rows& table) {
  std::string md = "| parameter | live setting | kind | default | min | max | unit | meaning |\n"
                   "|---|---|---|---|---|---|---|---|\n";
  for (const ParameterSpec& p : table) md += referenceRow(p);
  return md;
}

}  // namespace aurora_common
