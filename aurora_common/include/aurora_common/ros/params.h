// Strict parameter reading for every node (ROS parameter server): a missing or invalid parameter is
// an error naming the full key and the accepted values (no made-up defaults
// for vehicle constants).
#pragma once

#include <ros/ros.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

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

}  // namespace aurora_common
