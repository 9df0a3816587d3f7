// Writes Controller.cfg's live settings at build time (aurora_control's
// CMakeLists.txt): every controller parameter with a live name
// (loop/controller_parameters.h: the live laws' gains, the delay, the link's
// values, the predictor), as a YAML list of name, type (double or str),
// default, min, max and description, which the .cfg hands to
// dynamic_reconfigure's generator. Every number is a double, so that a value
// such as 2.5 samples reaches the node (which refuses it) instead of being
// truncated by the client.
//   controller_live_settings FILE
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>

#include "aurora_control/loop/controller_parameters.h"

namespace {

using aurora_control::ParameterSpec;
using aurora_control::ParamKind;

// The description rqt shows: the meaning, the unit, a word's choices.
std::string description(const ParameterSpec& p) {
  std::string d = p.doc;
  if (p.unit[0] != '\0') d += std::string(" [") + p.unit + "]";
  if (p.kind != ParamKind::kWord) return d;
  return d + " (" + aurora_control::joinKeys(aurora_control::paramChoices(p)) + ")";
}

// One setting: a word is a string among its choices (the node refuses
// others); any other value a double in the row's range, its default the
// row's (none: the minimum; the node starts from its files anyway).
void emitSetting(YAML::Emitter& out, const ParameterSpec& p) {
  out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.live;
  if (p.kind == ParamKind::kWord) {
    out << YAML::Key << "type" << YAML::Value << "str" << YAML::Key << "default" << YAML::Value
        << aurora_control::paramChoices(p).at(static_cast<size_t>(p.default_value));
  } else {
    out << YAML::Key << "type" << YAML::Value << "double" << YAML::Key << "default" << YAML::Value
        << (std::isnan(p.default_value) ? p.min : p.default_value) << YAML::Key << "min" << YAML::Value << p.min
        << YAML::Key << "max" << YAML::Value << p.max;
  }
  out << YAML::Key << "description" << YAML::Value << description(p) << YAML::EndMap;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: controller_live_settings FILE (Controller.cfg's live settings, YAML)\n";
    return 2;
  }
  YAML::Emitter out;
  out.SetDoublePrecision(std::numeric_limits<double>::max_digits10);  // every limit read back exactly
  out.SetStringFormat(YAML::DoubleQuoted);  // a word stays a word ("off" is no boolean to Python's reader)
  out << YAML::BeginSeq;
  for (const ParameterSpec& p : aurora_control::controllerParameters()) {
    if (p.live != nullptr) emitSetting(out, p);
  }
  out << YAML::EndSeq;
  std::ofstream file(argv[1]);
  file << out.c_str() << "\n";
  if (!file) {
    std::cerr << "controller_live_settings: cannot write " << argv[1] << "\n";
    return 1;
  }
  return 0;
}
