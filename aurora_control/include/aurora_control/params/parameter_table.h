// The loop's and the controller nodes' own parameters, written once
// (docs/architecture.md, "The parameter table"): each one's name, kind,
// default, accepted range, unit and meaning. A law's gains are not here: each
// law declares its own (its gainRow, law_gain_rows.h), and
// loop/controller_parameters.h joins both into the controller's parameters,
// whose reference is docs/parameters.md's and whose live rows are
// Controller.cfg's. The controller node, replay, flight, the sweep and the
// live settings take these limits from here through limits.h.
#pragma once

#include <string>

#include "aurora_common/parameter_spec.h"

namespace aurora_control {

using aurora_common::kNoValue;
using aurora_common::ParameterSpec;
using aurora_common::ParamKind;
using aurora_common::paramChoices;

// The rows, named.
enum ParameterRow : int {
  kRowDelaySamples,
  kRowDelaySeconds,
  kRowClampCommands,
  kRowMode,
  kRowTrigger,
  kRowLockstepCmdSubscribers,
  kRowLockstepControlSubscribers,
  kRowUplinkJitter,  // the link's live values: uplink jitter max, loss, burst; downlink delay, jitter max, loss, burst
  kRowUplinkLoss,
  kRowUplinkBurst,
  kRowDownlinkDelay,
  kRowDownlinkJitter,
  kRowDownlinkLoss,
  kRowDownlinkBurst,
  kRowPredictorForm,
  kRowRecordSubscribers,
  kParameterRows,
};

constexpr ParameterSpec kParameterTable[kParameterRows] = {
    {"delay/samples", ParamKind::kWholeSamples, 0.0, 0.0, 2047.0, "samples of Ts",
     "feedback delay, the link's uplink delay (sweep: delay); also shorter than the task's steps", nullptr,
     "delay_samples"},
    {"delay/seconds", ParamKind::kReal, kNoValue, 0.0, kNoValue, "s",
     "the delay in seconds instead, rounded once to whole samples, which then meet delay/samples' range"},
    {"clamp_commands", ParamKind::kBool, 1.0, 0.0, 1.0, "",
     "the controller clamps its commands to [-1, 1] as the drivers do (sweep files: default false, the study's)"},
    {"mode", ParamKind::kWord, 0, 0, 1, "",
     "controller node: realtime (30 Hz timer, states as they come) or lockstep (one command per simulated step)",
     "realtime|lockstep"},
    {"trigger", ParamKind::kWord, 0, 0, 1, "",
     "controller node, realtime: run the law on each new state, or on the timer with the newest state",
     "state|timer"},
    {"lockstep_subscribers/cmd_vel", ParamKind::kWhole, 1, 0, 100, "subscribers",
     "controller node, lockstep: subscribers of cmd_vel to wait for before the first command"},
    {"lockstep_subscribers/control", ParamKind::kWhole, 0, 0, 100, "subscribers",
     "controller node, lockstep: subscribers of control to wait for (a recorder, a test)"},
    {"link/uplink/jitter/max", ParamKind::kWholeSamples, 0, 0, 2047, "samples of Ts",
     "link (docs/links.md): the state packets' jitter, at most (the file's kind; uniform if it has none)", nullptr,
     "uplink_jitter"},
    {"link/uplink/loss", ParamKind::kReal, 0, 0, 0.99, "", "link: the long-run share of state packets lost",
     nullptr, "uplink_loss"},
    {"link/uplink/burst", ParamKind::kReal, 1, 1, 1000, "samples",
     "link: mean run of lost state packets (1: independent losses)", nullptr, "uplink_burst"},
    {"link/downlink/delay", ParamKind::kWholeSamples, 0, 0, 2047, "samples of Ts",
     "link: the command packets' base delay", nullptr, "downlink_delay"},
    {"link/downlink/jitter/max", ParamKind::kWholeSamples, 0, 0, 2047, "samples of Ts",
     "link: the command packets' jitter, at most", nullptr, "downlink_jitter"},
    {"link/downlink/loss", ParamKind::kReal, 0, 0, 0.99, "", "link: the long-run share of command packets lost",
     nullptr, "downlink_loss"},
    {"link/downlink/burst", ParamKind::kReal, 1, 1, 1000, "samples",
     "link: mean run of lost command packets (1: independent losses)", nullptr, "downlink_burst"},
    {"predictor/form", ParamKind::kWord, 0, 0, 2, "",
     "state predictor (docs/predictor.md): the law flies on the state of the step its command acts on, predicted by "
     "a model (predictor/model; live: the node's vehicle file when none was given)",
     "off|resimulate|smith", "predictor"},
    {"record_subscribers", ParamKind::kWhole, 0, 0, 100, "subscribers",
     "controller and formation nodes, both modes: subscribers of control (formation) that record the flight; no state "
     "is taken before they are connected, so a bag holds the loop from its first cycle (record:=true sets 1)"},
};

// The row of `rows` (an array or a vector) with live setting `live`, or nullptr.
template <class Rows>
const ParameterSpec* rowWithLiveName(const Rows& rows, const std::string& live) {
  for (const ParameterSpec& p : rows) {
    if (p.live != nullptr && live == p.live) return &p;
  }
  return nullptr;
}

// The row of this table with live setting `live`, or nullptr (a law's gain:
// loop/controller_parameters.h).
inline const ParameterSpec* rowOfLiveSetting(const std::string& live) { return rowWithLiveName(kParameterTable, live); }

}  // namespace aurora_control
