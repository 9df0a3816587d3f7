// The names a sweep file may vary, per controller, and each one's accepted
// range (host only). Model parameters are factors of the vehicle file's
// value: m 1.2 flies a drone 20 % heavier than config/vehicles/ardrone2.yaml
// (docs/delay-and-study.md, "Sweeping any parameter").
#pragma once

#include <string>
#include <vector>

#include "aurora_control/formation/shapes.h"
#include "aurora_sweep/combination.h"

namespace aurora_sweep {

enum class ParamGroup {
  kDelay, kModelFactor, kLink, kRepeat, kDroneDelay, kFormationGain, kDroneLink, kUnused,
  kLawGain,       // a law's own gain, its declaration's (law_gain_rows.h, sweep_gains.h)
  kFormationLaw,  // a triangle's law (kParamFormationLaw)
  kRobotGain,     // a formation robot's own law's gain (robot_gains.h)
};

// A sweep's shape (sweep file `formation:`; single-robot sweeps: kNone):
// 1 + its entry's place in the shapes' list (aurora_control/formation/
// shapes.h), sweepShapeOf<Entry>(). The shapes' parameters share one room
// (combination.h, ShapeLayout), so a parameter's name is its shape's (its
// entry's ParamShape's): the line's and the UAV-UGV line's are the same (2
// robots, 6 variables), the triangle's its own.
enum class SweepShape : int { kNone = 0 };
constexpr int kSweepShapeCount = 1 + aurora_control::KnownShapes::kCount;
template <class Entry>
constexpr SweepShape sweepShapeOf() {
  return static_cast<SweepShape>(1 + aurora_control::shapeIndex<Entry>());
}
// "none", else its entry's name.
const char* sweepShapeName(SweepShape shape);
// The laws a sweep of `shape` may vary (formation_law's values: the index
// of a name here), its entry's sweepLawNames in order; none for a shape
// that flies its file's law.
std::vector<std::string> formationLawNames(SweepShape shape);
// f(Entry()) for the entry of `shape`; none for kNone.
template <class F>
void withSweepShape(SweepShape shape, F&& f) {
  aurora_control::forEachShape([&](auto e) {
    if (shape == sweepShapeOf<decltype(e)>()) f(e);
  });
}

struct ParamInfo {
  std::string name;
  ParamGroup group;
  double min, max;    // accepted values (inclusive)
  std::string limit;  // why: shown when a value or range is refused
  bool whole = false; // whole samples only (the delays, the jitters)
  std::string law;    // a gain's: the controller whose gain it is (a name of the law list)
  double preset = 0;  // a kLawGain's default (the law's defaults())
};

// Parameter id's row in a sweep of `shape` (a formation's robot gains are
// the sweep's own rows: SweepSpec::param, SweepSpec::paramId by name).
const ParamInfo& paramInfo(int id, SweepShape shape);
// Factor slot i (0 .. kModelFactorCount - 1) of a single-robot sweep of a
// vehicle of type `vehicle_type`: its factorName(i) (the AR.Drone's m, Ixx,
// ...; the Bebop 2's Ku_x ... Kv_yaw; the Pioneer's theta1 ... theta6), or
// an unused row where it has fewer factors.
const ParamInfo& modelFactorInfo(const std::string& vehicle_type, int i);
// A short name; "kp", "k1_theta", "m", ...
inline const char* paramName(int id, SweepShape shape) { return paramInfo(id, shape).name.c_str(); }

// Whether a sweep of controller `controller` (a law's name) accepts the
// parameter of row `info` (its gains, the delay, its vehicle's model
// factors, the link); a formation sweep (shape not kNone) accepts its
// robots' delays, the formation's gains (a triangle's law), the link's
// values and its robots' own gains instead (SweepSpec::accepts; its
// acceptedNames lists them).
bool paramApplies(const ParamInfo& info, const std::string& controller, SweepShape shape);
// The value of a parameter a sweep file leaves out: the underactuated law's
// gains default to the spec's (UnderactuatedGains::defaults), the other
// vehicles' laws' gains to their defaults (sweep_gains.h), model factors
// to 1, the link's values to an ideal link's (a sweep's link file replaces
// them), the repeat to 0, the formation's gains to AuRoRA's (a formation
// file's replace them), a triangle's law to N (its file's replaces it). The PD gains and the delays have none (NaN: the file
// must give them).
double paramDefault(int id, SweepShape shape);

}  // namespace aurora_sweep
