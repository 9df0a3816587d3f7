// The simulator node's own parameters (vehicle_sim's private ~ parameters),
// written once as a parameter table (aurora_common/parameter_spec.h): the
// node reads every row through it, and docs/parameters.md's simulator
// reference is simParameterReference() (test_ardrone_model compares). The
// vehicle's constants are not here: they come from its vehicle file, every
// key required (each vehicle's fileKeys(), vehicle_keys.h).
#pragma once

#include <limits>
#include <string>

#include "aurora_common/parameter_spec.h"

namespace aurora_sim {

// Below this height [m] a landing drone is down; a take-off altitude must be above it.
constexpr double kLandedAltitude = 0.05;

enum SimParameterRow : int {
  kSimRowMode,
  kSimRowCmdTimeout,
  kSimRowTakeoffAltitude,
  kSimRowStartFlying,
  kSimRowStart,
  kSimRowStartAtStatePoint,
  kSimRowFrameId,
  kSimRowChildFrameId,
  kSimRowPathDecimation,
  kSimRowNanQuietPeriod,
  kSimRowNanSummaryPeriod,
  kSimRowStopAfter,
  kSimRowLockstepSubscribers,
  kSimRowMaxRealTimeFactor,
  kSimRowPublishClock,
  kSimParameterRows,
};

namespace sim_rows {
using aurora_common::kNoValue;
using aurora_common::ParamKind;
constexpr double kNoLimit = std::numeric_limits<double>::max();
}  // namespace sim_rows

constexpr aurora_common::ParameterSpec kSimParameterTable[kSimParameterRows] = {
    {"mode", sim_rows::ParamKind::kWord, 0, 0, 0, "",
     "realtime (a timer at the vehicle's rate, the last command held) or lockstep (one model step per command; "
     "the sim owns /clock)", "realtime|lockstep", nullptr, false, nullptr},
    {"cmd_timeout", sim_rows::ParamKind::kReal, 0.2, 0.0, 10.0, "s",
     "realtime: with no command for this long the drone hovers (the drivers' watchdog)", nullptr, nullptr, true,
     nullptr},
    {"takeoff_altitude", sim_rows::ParamKind::kReal, 0.75, kLandedAltitude, 5.0, "m",
     "take-off climbs to this height", nullptr, nullptr, true, nullptr},
    {"start_flying", sim_rows::ParamKind::kBool, 1, 0, 1, "",
     "start in the air at the start point (the study's initial state); false starts landed", nullptr, nullptr,
     false, nullptr},
    {"start", sim_rows::ParamKind::kPoint, sim_rows::kNoValue, sim_rows::kNoValue, sim_rows::kNoValue, "m",
     "the start point [x, y, z] (world frame)", nullptr, nullptr, false, "[0, 0, 0.75]"},
    {"start_at_state_point", sim_rows::ParamKind::kBool, 0, 0, 1, "",
     "~start is the point the state gives (a ground robot's control point, ahead of its centre), as a formation "
     "file's starts are (formation.launch); false: the body's centre", nullptr, nullptr, false, nullptr},
    {"frame_id", sim_rows::ParamKind::kText, sim_rows::kNoValue, sim_rows::kNoValue, sim_rows::kNoValue, "",
     "the world frame of odom, path and tf", nullptr, nullptr, false, "world"},
    {"child_frame_id", sim_rows::ParamKind::kText, sim_rows::kNoValue, sim_rows::kNoValue, sim_rows::kNoValue, "",
     "the body frame of odom and tf", nullptr, nullptr, false, "NS/base_link (base_link without a namespace)"},
    {"path_decimation", sim_rows::ParamKind::kWhole, 3, 1, sim_rows::kNoValue, "steps",
     "one pose of the path topic every this many steps", nullptr, nullptr, false, nullptr},
    {"nan_burst/quiet_period", sim_rows::ParamKind::kReal, 1.0, 0.0, 60.0, "s",
     "rejected (non-finite) commands: a burst ends after this long without one", nullptr, nullptr, true, nullptr},
    {"nan_burst/summary_period", sim_rows::ParamKind::kReal, 5.0, 0.1, 3600.0, "s",
     "rejected commands: a long burst is summarised in the log this often", nullptr, nullptr, false, nullptr},
    {"stop_after", sim_rows::ParamKind::kReal, 0.0, 0.0, sim_rows::kNoLimit, "s",
     "stop the node after this much simulated time (0: run until stopped)", nullptr, nullptr, false, nullptr},
    {"lockstep_subscribers", sim_rows::ParamKind::kWhole, 1, 0, sim_rows::kNoValue, "subscribers",
     "lockstep: subscribers of state to wait for before the first step", nullptr, nullptr, false, nullptr},
    {"max_real_time_factor", sim_rows::ParamKind::kReal, 0.0, 0.0, sim_rows::kNoLimit, "",
     "lockstep: at most this many simulated seconds per wall second (0: as fast as possible)", nullptr, nullptr,
     false, nullptr},
    {"publish_clock", sim_rows::ParamKind::kBool, 1, 0, 1, "",
     "lockstep: publish /clock (formation.launch: one sim of several owns it; a second owner is refused)", nullptr,
     nullptr, false, nullptr},
};

// The table as docs/parameters.md's simulator reference (between its markers).
inline std::string simParameterReference() { return aurora_common::parameterReference(kSimParameterTable); }

}  // namespace aurora_sim
