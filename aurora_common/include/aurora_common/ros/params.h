// Strict parameter reading for every node (ROS parameter server): a missing or invalid parameter is
// an error naming the full key and the accepted values (no made-up defaults
// for vehicle constants).
#pragma once

#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "aurora_common/parameter_spec.h"
#include "aurora_common/refusal_text.h"

namespace aurora_common {

inline std::string fullKey(const ros::NodeHandle& nh, const std::string& key) {
  return nh.resolveName(key);
}

template <typename V>
V requireParam(const ros::NodeHandle& nh, const std::string& key, const std::string& accepted) {
  V value;
  if (!nh.getParam(key, value)) {
    throw ConfigError("missing parameter '" + fullKey(nh, key) + "' (accepted: " + accepted +
                         ")");
  }
  return value;
}

template <typename V>
V paramOr(const ros::NodeHandle& nh, const std::string& key, const V& fallback) {
  V value;
  return nh.getParam(key, value) ? value : fallback;
}

// An optional boolean with a default, by the one boolean rule (refusal_text.h).
inline bool boolParam(const ros::NodeHandle& nh, const std::string& key, bool fallback) {
  XmlRpc::XmlRpcValue v;
  if (!nh.getParam(key, v)) return fallback;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeBoolean) return static_cast<bool>(v);
  const std::string text = v.getType() == XmlRpc::XmlRpcValue::TypeString ? static_cast<std::string>(v) : v.toXml();
  throw ConfigError("parameter " + booleanRefusal(fullKey(nh, key), text));
}

// An optional number with a default, checked against [lo, hi] (or (lo, hi]
// with lo_inclusive false); the error names the full key, the value and the range.
inline double rangedParam(const ros::NodeHandle& nh, const std::string& key, double fallback,
                          double lo, double hi, const std::string& unit,
                          bool lo_inclusive = true) {
  const double v = paramOr(nh, key, fallback);
  const bool above = lo_inclusive ? v >= lo : v > lo;
  if (!(std::isfinite(v) && above && v <= hi)) {
    // No upper limit reads as "inf)", not as DBL_MAX's 309 digits.
    const bool open = hi >= std::numeric_limits<double>::max();
    throw ConfigError("parameter '" + fullKey(nh, key) + "' = " + numberText(v) +
                         " is invalid: accepted range " + (lo_inclusive ? "[" : "(") + numberText(lo) +
                         ", " + (open ? std::string("inf)") : numberText(hi) + "]") + " " + unit);
  }
  return v;
}

// A row of a parameter table (parameter_spec.h) as a node's private
// parameter, its default when absent; refused with the full key and what is
// accepted. A number within the row's range:
inline double tableParam(const ros::NodeHandle& nh, const ParameterSpec& row) {
  const double hi = std::isnan(row.max) ? std::numeric_limits<double>::max() : row.max;
  return rangedParam(nh, row.name, row.default_value, row.min, hi, row.unit, !row.min_excluded);
}

// A whole number within the row's range (an integer, or a real without a
// fraction; 2.5 is refused, not truncated).
inline long wholeParam(const ros::NodeHandle& nh, const ParameterSpec& row) {
  XmlRpc::XmlRpcValue v;
  if (nh.getParam(row.name, v) && v.getType() != XmlRpc::XmlRpcValue::TypeInt &&
      !(v.getType() == XmlRpc::XmlRpcValue::TypeDouble && std::floor(double(v)) == double(v))) {
    throw ConfigError("parameter '" + fullKey(nh, row.name) + "' = " + v.toXml() +
                      " is invalid: accepted a whole number from " + numberText(row.min) +
                      (std::isnan(row.max) ? std::string(" up") : " to " + numberText(row.max)));
  }
  return static_cast<long>(tableParam(nh, row));
}

// One of a word row's words.
inline std::string wordParam(const ros::NodeHandle& nh, const ParameterSpec& row) {
  const std::vector<std::string> words = paramChoices(row);
  const std::string value = paramOr<std::string>(nh, row.name, words[static_cast<size_t>(row.default_value)]);
  if (std::find(words.begin(), words.end(), value) == words.end()) {
    std::string accepted;
    for (const std::string& w : words) accepted += (accepted.empty() ? "'" : ", '") + w + "'";
    throw ConfigError("parameter '" + fullKey(nh, row.name) + "' = '" + value + "' is invalid: accepted values " +
                      accepted);
  }
  return value;
}

// A flag row, by the one boolean rule.
inline bool flagParam(const ros::NodeHandle& nh, const ParameterSpec& row) {
  return boolParam(nh, row.name, row.default_value != 0.0);
}

// A text row (a frame name); `fallback` where the row's default depends on
// the node (its namespace).
inline std::string textParam(const ros::NodeHandle& nh, const ParameterSpec& row, const std::string& fallback) {
  return paramOr<std::string>(nh, row.name, fallback);
}

}  // namespace aurora_common
