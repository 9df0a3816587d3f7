// The result columns of a sweep, written once: after `index` and the swept
// parameters, these columns in this order, in results.csv, results.h5 and
// summary.json ("result_columns", which plot_sweep reads).
#pragma once

#include <cstdint>

#include "aurora_sweep/simulation.h"

namespace aurora_sweep {

// How a column is stored: a 0/1 flag (uint8), a double, an int32, a float.
enum class ColumnType { kFlag, kDouble, kInt32, kFloat };

// Where a column's value sits in the record (SimResult): a bit of ok, one
// of the three doubles, steps, one of the three floats, or extra.
enum class ColumnField { kBit, kDouble, kSteps, kFloat, kExtra };

struct ResultColumn {
  const char* name;
  ColumnType type;
  const char* unit;  // "" for none
  const char* doc;
  ColumnField field;
  int at;  // kBit: the bit; kDouble, kFloat: which of the three
};

constexpr ResultColumn kResultColumns[] = {
    {"ok1", ColumnType::kFlag, "", "check 1 held: true error within max_error", ColumnField::kBit, checkBit(0)},
    {"ok2", ColumnType::kFlag, "", "check 2 held: IAE within max_iae", ColumnField::kBit, checkBit(1)},
    {"ok3", ColumnType::kFlag, "", "check 3 held: ITAE within max_itae", ColumnField::kBit, checkBit(2)},
    {"ok4", ColumnType::kFlag, "", "check 4 held: true error within error_growth times the initial error",
     ColumnField::kBit, checkBit(3)},
    {"feasible", ColumnType::kFlag, "", "all four checks held", ColumnField::kBit, kFeasibleBit},
    {"iae", ColumnType::kDouble, "m s", "integral of the controller's position error", ColumnField::kDouble, 0},
    {"itae", ColumnType::kDouble, "m s^2", "integral of the loop clock's time times that error", ColumnField::kDouble, 1},
    {"iasc", ColumnType::kDouble, "s", "integral of the command's norm", ColumnField::kDouble, 2},
    {"steps", ColumnType::kInt32, "", "model steps run (fewer with early_stop)", ColumnField::kSteps, 0},
    {"x", ColumnType::kFloat, "m", "final position, world frame", ColumnField::kFloat, 0},
    {"y", ColumnType::kFloat, "m", "final position, world frame", ColumnField::kFloat, 1},
    {"z", ColumnType::kFloat, "m", "final position, world frame", ColumnField::kFloat, 2},
};

// A formation sweep's columns: the same record (formation_simulation.h's
// FormationRecord), named for the formation's checks (docs/formation.md,
// "Formation checks").
constexpr ResultColumn kFormationResultColumns[] = {
    {"ok1", ColumnType::kFlag, "", "check 1 held: formation position error within max_position_error after settle_time",
     ColumnField::kBit, checkBit(0)},
    {"ok2", ColumnType::kFlag, "", "check 2 held: shape error within max_shape_error after settle_time",
     ColumnField::kBit, checkBit(1)},
    {"ok3", ColumnType::kFlag, "", "check 3 held: both errors' integrals within max_iae_position and max_iae_shape",
     ColumnField::kBit, checkBit(2)},
    {"ok4", ColumnType::kFlag, "", "check 4 held: the drones never closer than min_distance (no collision)",
     ColumnField::kBit, checkBit(3)},
    {"ok5", ColumnType::kFlag, "",
     "check 5 held: every ground robot's commands within max_ground_speed and max_ground_turn_rate (always, without one)",
     ColumnField::kBit, checkBit(4)},
    {"feasible", ColumnType::kFlag, "", "all five checks held", ColumnField::kBit, kFeasibleBit},
    {"iae_position", ColumnType::kDouble, "m s", "integral of the formation position error after settle_time",
     ColumnField::kDouble, 0},
    {"iae_shape", ColumnType::kDouble, "m s", "integral of the shape error after settle_time", ColumnField::kDouble, 1},
    {"min_distance", ColumnType::kDouble, "m", "smallest distance between the drones", ColumnField::kDouble, 2},
    {"steps", ColumnType::kInt32, "", "ticks run (fewer with early_stop)", ColumnField::kSteps, 0},
    {"max_position_error", ColumnType::kFloat, "m", "largest formation position error after settle_time",
     ColumnField::kFloat, 0},
    {"max_shape_error", ColumnType::kFloat, "m", "largest shape error after settle_time", ColumnField::kFloat, 1},
    {"end_distance", ColumnType::kFloat, "m", "distance between the drones at the end", ColumnField::kFloat, 2},
    {"ground_command", ColumnType::kFloat, "",
     "the largest share of check 5's limits a ground robot's commands used (over 1: check 5 failed; 0: no ground robot)",
     ColumnField::kExtra, 0},
};

// The columns of a sweep, a formation sweep's or the single drone's.
struct ResultColumnList {
  const ResultColumn* columns;
  int count;
  const ResultColumn& operator[](int k) const { return columns[k]; }
};
inline ResultColumnList resultColumns(bool formation) {
  constexpr int one = static_cast<int>(sizeof kResultColumns / sizeof kResultColumns[0]);
  constexpr int shape = static_cast<int>(sizeof kFormationResultColumns / sizeof kFormationResultColumns[0]);
  return formation ? ResultColumnList{kFormationResultColumns, shape} : ResultColumnList{kResultColumns, one};
}

// A column's value of a result, in the column's type.
struct ColumnValue {
  ColumnType type;
  union {
    uint8_t flag;
    double real;
    int32_t whole;
    float single;
  };
};

inline ColumnValue columnValue(const SimResult& r, const ResultColumn& c) {
  ColumnValue v;
  v.type = c.type;
  const double reals[3] = {r.iae, r.itae, r.iasc};
  switch (c.field) {
    case ColumnField::kBit: v.flag = static_cast<uint8_t>((r.ok >> c.at) & 1); break;
    case ColumnField::kDouble: v.real = reals[c.at]; break;
    case ColumnField::kSteps: v.whole = static_cast<int32_t>(r.steps); break;
    case ColumnField::kFloat: v.single = r.final_pos[c.at]; break;
    case ColumnField::kExtra: v.single = r.extra; break;
  }
  return v;
}

}  // namespace aurora_sweep
