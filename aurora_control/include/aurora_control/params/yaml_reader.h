// Strict reading of YAML configuration (yaml-cpp), ROS-free: every refusal
// names the full key, what is accepted, and the file or parameter it came
// from. Used by the task loader (node, replay, sweep) and the sweep file.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_common/refusal_text.h"
#include "aurora_common/yaml_file.h"

namespace aurora_control {

using aurora_common::ConfigError;  // refusal_text.h: the one error type

inline std::string joinKeys(const std::vector<std::string>& keys) {
  std::string out;
  for (const auto& k : keys) out += (out.empty() ? "" : ", ") + k;
  return out;
}

// A YAML file's root, duplicated keys refused (aurora_common/yaml_file.h).
using aurora_common::loadYamlFile;

class YamlReader {
 public:
  // context: where the values come from, prefixed to every message (e.g.
  // "sweep file 'a.yaml': "); separator: between key levels ("." in files,
  // "/" for ROS parameters).
  explicit YamlReader(std::string context = "", std::string separator = ".")
      : context_(std::move(context)), sep_(std::move(separator)) {}

  std::string key(const std::string& parent, const std::string& name) const {
    return parent.empty() ? name : parent + sep_ + name;
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw ConfigError(context_ + "'" + key + "' " + what);
  }
  // A message that already names its key.
  [[noreturn]] void failWith(const std::string& message) const { throw ConfigError(context_ + message); }
  const std::string& separator() const { return sep_; }
  const std::string& context() const { return context_; }

  void onlyKeys(const YAML::Node& node, const std::string& key,
                const std::vector<std::string>& accepted) const {
    if (!node.IsMap()) fail(key, "must be a mapping with keys: " + joinKeys(accepted));
    for (const auto& kv : node) {
      const std::string name = kv.first.as<std::string>();
      if (std::find(accepted.begin(), accepted.end(), name) == accepted.end()) {
        fail(this->key(key, name), "is not a known key: accepted " + joinKeys(accepted));
      }
    }
  }

  const YAML::Node require(const YAML::Node& parent, const std::string& parent_key,
                           const std::string& name, const std::string& accepted) const {
    const YAML::Node n = parent[name];
    if (!n) fail(key(parent_key, name), "is missing; accepted: " + accepted);
    return n;
  }

  double number(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) fail(key, "has the wrong type: expected a number");
    // A quoted scalar ("0.5") is a string, whatever it reads as.
    if (node.Tag() == "!") fail(key, "= '" + node.as<std::string>() + "' has the wrong type: expected a number, not a string" + exponentHint(node.as<std::string>()));
    double v = 0.0;
    try {
      v = node.as<double>();
    } catch (const YAML::Exception&) {
      fail(key, "= '" + node.as<std::string>() + "' has the wrong type: expected a number");
    }
    if (!std::isfinite(v)) fail(key, "must be a finite number");
    return v;
  }

  double numberIn(const YAML::Node& node, const std::string& key, double lo, double hi,
                  const std::string& unit, bool lo_inclusive = true) const {
    const double v = number(node, key);
    if (!((lo_inclusive ? v >= lo : v > lo) && v <= hi)) {
      fail(key, "= " + fmt(v) + " is outside the accepted range " + (lo_inclusive ? "[" : "(") +
                    fmt(lo) + ", " + fmt(hi) + "] " + unit);
    }
    return v;
  }

  long integer(const YAML::Node& node, const std::string& key) const {
    const double v = number(node, key);
    if (v != std::floor(v)) fail(key, "must be a whole number, got " + node.as<std::string>());
    return static_cast<long>(v);
  }

  // The one boolean rule (aurora_common/refusal_text.h): a quoted scalar is a
  // string, even "false".
  bool boolean(const YAML::Node& node, const std::string& key) const {
    const std::string text = node.IsScalar() ? node.as<std::string>() : std::string("(not a scalar)");
    if (node.IsScalar() && node.Tag() != "!") {
      try {
        return node.as<bool>();
      } catch (const YAML::Exception&) {
      }
    }
    failWith(aurora_common::booleanRefusal(key, text));
  }

  std::string text(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) fail(key, "must be a string");
    return node.as<std::string>();
  }

  // A list of exactly n numbers.
  std::vector<double> numbers(const YAML::Node& node, const std::string& key, size_t n,
                              const std::string& what) const {
    if (!node.IsSequence() || node.size() != n) fail(key, "must be " + what);
    std::vector<double> v;
    for (size_t i = 0; i < n; ++i) v.push_back(number(node[i], key + "[" + std::to_string(i) + "]"));
    return v;
  }

  // A threshold: a number, or [factor, base] meaning factor x base as the
  // thesis writes its limits (30 x 5.3218).
  double threshold(const YAML::Node& node, const std::string& key) const {
    if (node.IsSequence()) {
      if (node.size() != 2) fail(key, "must be a number or [factor, base]");
      return number(node[0], key + "[0]") * number(node[1], key + "[1]");
    }
    return number(node, key);
  }

  // YAML 1.1 (rosparam, roslaunch) reads 1.0e9 as text: it wants a dot and a
  // signed exponent. Says how to write such a number; "" for other strings.
  static std::string exponentHint(const std::string& text) {
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    const size_t e = text.find_first_of("eE");
    if (text.empty() || *end != '\0' || e == std::string::npos) return "";
    std::string fixed = text.substr(0, e);
    if (fixed.find('.') == std::string::npos) fixed += ".0";
    const std::string exponent = text.substr(e + 1);
    fixed += "e" + std::string(exponent[0] == '+' || exponent[0] == '-' ? "" : "+") + exponent;
    return " (YAML 1.1, which rosparam reads, takes '" + text + "' as text: write " + fixed + ")";
  }

  static std::string fmt(double v) { return aurora_common::numberText(v); }

 private:
  std::string context_;
  std::string sep_;
};

}  // namespace aurora_control
