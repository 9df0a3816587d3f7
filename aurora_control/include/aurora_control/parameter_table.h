// The loop's parameters, written once (docs/architecture.md, "The parameter
// table"): each one's name, kind, default, accepted range, unit and meaning.
// The controller node, replay, flight, the sweep and the live settings
// (dynamic_reconfigure) take their limits from here through limits.h; a test
// checks Controller.cfg's limits against it and another that the README's
// parameter reference is parameterReference() of this table.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace aurora_control {

enum class ParamKind { kReal, kWholeSamples, kBool };

struct ParameterSpec {
  const char* name;      // in the controller YAML and ROS parameters (sweep files and reconfigure: see doc)
  ParamKind kind;
  double default_value;  // NaN: none, the file must give it
  double min, max;       // accepted values, inclusive (NaN max: see doc)
  const char* unit;      // "" for none
  const char* doc;
};

// The rows, named.
enum ParameterRow : int {
  kRowKp,
  kRowKd,
  kRowDelaySamples,
  kRowDelaySeconds,
  kRowClampCommands,
  kRowFirstUnderactuatedGain,  // k1_x, k2_x, k1_y, ... k2_psi (underactuatedGainName order)
  kParameterRows = kRowFirstUnderactuatedGain + 12,
};

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

constexpr ParameterSpec kParameterTable[kParameterRows] = {
    {"kp", ParamKind::kReal, kNoValue, 0.0, 10.0, "",
     "PD law (pd_saturated): gain on the tanh-saturated position error (eq. 3.1)"},
    {"kd", ParamKind::kReal, kNoValue, 0.0, 10.0, "",
     "PD law: gain on the tanh-saturated velocity error"},
    {"delay/samples", ParamKind::kWholeSamples, 0.0, 0.0, 2047.0, "samples of Ts",
     "feedback delay (sweep: delay; reconfigure: delay_samples); also shorter than the task's steps"},
    {"delay/seconds", ParamKind::kReal, kNoValue, 0.0, kNoValue, "s",
     "the delay in seconds instead, rounded once to whole samples, which then meet delay/samples' range"},
    {"clamp_commands", ParamKind::kBool, 1.0, 0.0, 1.0, "",
     "the controller clamps its commands to [-1, 1] as the drivers do (sweep files: default false, the study's)"},
    {"k1_x", ParamKind::kReal, 0.5, 0.001, 100.0, "", "underactuated law: k1 of x"},
    {"k2_x", ParamKind::kReal, 2.0, 0.001, 100.0, "", "underactuated law: k2 of x"},
    {"k1_y", ParamKind::kReal, 0.5, 0.001, 100.0, "", "underactuated law: k1 of y"},
    {"k2_y", ParamKind::kReal, 2.0, 0.001, 100.0, "", "underactuated law: k2 of y"},
    {"k1_z", ParamKind::kReal, 5.0, 0.001, 100.0, "", "underactuated law: k1 of z"},
    {"k2_z", ParamKind::kReal, 2.0, 0.001, 100.0, "", "underactuated law: k2 of z"},
    {"k1_phi", ParamKind::kReal, 1.0, 0.001, 100.0, "", "underactuated law: k1 of roll"},
    {"k2_phi", ParamKind::kReal, 20.0, 0.001, 100.0, "", "underactuated law: k2 of roll"},
    {"k1_theta", ParamKind::kReal, 1.0, 0.001, 100.0, "", "underactuated law: k1 of pitch"},
    {"k2_theta", ParamKind::kReal, 20.0, 0.001, 100.0, "", "underactuated law: k2 of pitch"},
    {"k1_psi", ParamKind::kReal, 1.0, 0.001, 100.0, "", "underactuated law: k1 of yaw"},
    {"k2_psi", ParamKind::kReal, 2.5, 0.001, 100.0, "", "underactuated law: k2 of yaw"},
};

inline const char* paramKindName(ParamKind k) {
  return k == ParamKind::kReal ? "real" : k == ParamKind::kWholeSamples ? "whole" : "bool";
}

// One value of the reference: "—" for none, true/false for a flag.
inline std::string referenceValue(const ParameterSpec& p, double v) {
  if (std::isnan(v)) return "—";
  if (p.kind == ParamKind::kBool) return v != 0.0 ? "true" : "false";
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// The table as the README's markdown (the "Parameter reference" section).
inline std::string parameterReference() {
  std::string md = "| parameter | kind | default | min | max | unit | meaning |\n|---|---|---|---|---|---|---|\n";
  for (const ParameterSpec& p : kParameterTable) {
    md += std::string("| `") + p.name + "` | " + paramKindName(p.kind) + " | " + referenceValue(p, p.default_value) +
          " | " + referenceValue(p, p.min) + " | " + referenceValue(p, p.max) + " | " + p.unit + " | " + p.doc + " |\n";
  }
  return md;
}

}  // namespace aurora_control
