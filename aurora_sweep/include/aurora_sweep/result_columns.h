// The result columns of a sweep, written once: after `index` and the swept
// parameters, these columns in this order, in results.csv, results.h5 and
// summary.json ("result_columns", which plot_sweep reads).
#pragma once

#include <cstdint>

#include "aurora_sweep/simulation.h"

namespace aurora_sweep {

// How a column is stored: a 0/1 flag (uint8), a double, an int32, a float.
enum class ColumnType { kFlag, kDouble, kInt32, kFloat };

struct ResultColumn {
  const char* name;
  ColumnType type;
  const char* unit;  // "" for none
  const char* doc;
};

// The columns' positions, named.
enum ResultColumnIndex : int {
  kColumnOk1 = 0,  // ok1..ok4 at 0..3: SimResult::ok's bits
  kColumnFeasible = 4,
  kColumnIae,
  kColumnItae,
  kColumnIasc,
  kColumnSteps,
  kColumnX,  // x, y, z
};
static_assert(kColumnFeasible == kFeasibleBit, "the flags are SimResult::ok's bits in order");

constexpr ResultColumn kResultColumns[] = {
    {"ok1", ColumnType::kFlag, "", "check 1 held: true error within max_error"},
    {"ok2", ColumnType::kFlag, "", "check 2 held: IAE within max_iae"},
    {"ok3", ColumnType::kFlag, "", "check 3 held: ITAE within max_itae"},
    {"ok4", ColumnType::kFlag, "", "check 4 held: true error within error_growth times the initial error"},
    {"feasible", ColumnType::kFlag, "", "all four checks held"},
    {"iae", ColumnType::kDouble, "m s", "integral of the controller's position error"},
    {"itae", ColumnType::kDouble, "m s^2", "integral of the loop clock's time times that error"},
    {"iasc", ColumnType::kDouble, "s", "integral of the command's norm"},
    {"steps", ColumnType::kInt32, "", "model steps run (fewer with early_stop)"},
    {"x", ColumnType::kFloat, "m", "final position, world frame"},
    {"y", ColumnType::kFloat, "m", "final position, world frame"},
    {"z", ColumnType::kFloat, "m", "final position, world frame"},
};
constexpr int kResultColumnCount = static_cast<int>(sizeof kResultColumns / sizeof kResultColumns[0]);

// A formation sweep's columns: the same record and types in the same places
// (formation_simulation.h's formationResult), named for the formation's
// checks (docs/formation.md, "Formation checks").
constexpr ResultColumn kFormationResultColumns[] = {
    {"ok1", ColumnType::kFlag, "", "check 1 held: formation position error within max_position_error after settle_time"},
    {"ok2", ColumnType::kFlag, "", "check 2 held: shape error within max_shape_error after settle_time"},
    {"ok3", ColumnType::kFlag, "", "check 3 held: both errors' integrals within max_iae_position and max_iae_shape"},
    {"ok4", ColumnType::kFlag, "", "check 4 held: the drones never closer than min_distance (no collision)"},
    {"feasible", ColumnType::kFlag, "", "all four checks held"},
    {"iae_position", ColumnType::kDouble, "m s", "integral of the formation position error after settle_time"},
    {"iae_shape", ColumnType::kDouble, "m s", "integral of the shape error after settle_time"},
    {"min_distance", ColumnType::kDouble, "m", "smallest distance between the drones"},
    {"steps", ColumnType::kInt32, "", "ticks run (fewer with early_stop)"},
    {"max_position_error", ColumnType::kFloat, "m", "largest formation position error after settle_time"},
    {"max_shape_error", ColumnType::kFloat, "m", "largest shape error after settle_time"},
    {"end_distance", ColumnType::kFloat, "m", "distance between the drones at the end"},
};
static_assert(sizeof kFormationResultColumns == sizeof kResultColumns, "one record, two namings");

// The columns of a sweep, a formation sweep's or the single drone's.
inline const ResultColumn* resultColumns(bool formation) {
  return formation ? kFormationResultColumns : kResultColumns;
}

// Column k's value of a result, in the column's type.
struct ColumnValue {
  ColumnType type;
  union {
    uint8_t flag;
    double real;
    int32_t whole;
    float single;
  };
};

inline ColumnValue columnValue(const SimResult& r, int k) {
  ColumnValue v;
  v.type = kResultColumns[k].type;
  switch (k) {
    case kColumnIae: v.real = r.iae; break;
    case kColumnItae: v.real = r.itae; break;
    case kColumnIasc: v.real = r.iasc; break;
    case kColumnSteps: v.whole = static_cast<int32_t>(r.steps); break;
    default:
      if (k <= kColumnFeasible) v.flag = static_cast<uint8_t>((r.ok >> k) & 1);
      else v.single = r.final_pos[k - kColumnX];
  }
  return v;
}

}  // namespace aurora_sweep
