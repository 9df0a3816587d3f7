// flight --formation: a formation file flown offline (formation_runner.h),
// its formation errors printed, its trajectory written as CSV; what every
// shape's flight shares (its options, the delays, the checks' text, the
// table of rows). Each shape's own flight is in its folder (line/
// line_flight.h; src/<shape>/<shape>_flight.cpp). The same flights from
// Python: aurora._core.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "aurora_common/number_text.h"
#include "aurora_control/formation/formation_checks.h"
#include "aurora_control/link/link.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

struct FormationFlightOptions {
  std::string formation, vehicle, csv, config_dir;
  std::vector<long> delays;  // per drone, replacing the file's (empty: the file's)
  std::string law;           // a triangle's law instead of the file's (flight --law; empty: the file's)
};

// --delay's per-robot delays [samples of Ts] for a formation of `robots`
// (none given: `none`), each in the delay rule's range and shorter than the
// run's `ticks`; refused naming the `robot` ("drone", "robot") by its number
// and `shape` ("the line", ...).
std::vector<long> robotDelays(const std::vector<long>& given, size_t robots, const std::string& shape, double Ts,
                              long ticks, const std::vector<long>& none, const std::string& robot = "robot");

// Robot r's (0-based) link with its delay: its latest packet inside the
// run's `ticks`, its history within the delay history; refused naming it.
void refuseRobotLink(const LinkParams& link, long delay, int r, long ticks, double Ts);

// Robot r's delay in a run of `ticks` steps: shorter than the run (the
// delay's own refusal, which names no link), then its link's packets
// (refuseRobotLink). The one rule of flight --formation and the formation
// node (src/crew_of.h), for every shape.
void refuseRobotDelay(const LinkParams& link, long delay, int r, long ticks, double Ts);

// The formation checks (docs/formation.md, "Formation checks") as a sweep
// judges them, as the flight tool prints them: check 5 where the formation
// has a ground robot.
template <class Shape>
std::string checksText(const FormationCriteria<double>& c, const FormationMetrics<double, bool, Shape>& m,
                       bool ground_robot) {
  const auto held = [&](int i) { return m.ok[i] ? "held" : "FAILED"; };
  char text[600], ground[200] = "";
  if (ground_robot) {
    std::snprintf(ground, sizeof ground, "; 5 ground commands at most %.3f of %g m/s, %g rad/s %s", m.ground_command,
                  c.max_ground_speed, c.max_ground_turn_rate, held(4));
  }
  std::snprintf(text, sizeof text,
                "  checks from %.0f s: 1 position error max %.4f m (<= %g) %s; 2 shape error max %.4f m (<= %g) %s;\n"
                "    3 IAE position %.4f m s (<= %g), shape %.4f m s (<= %g) %s; 4 smallest distance %.4f m (>= %g) "
                "%s%s: %s\n",
                c.settle_time, m.max_position, c.max_position_error, held(0), m.max_shape, c.max_shape_error, held(1),
                m.iae_position, c.max_iae_position, m.iae_shape, c.max_iae_shape, held(2), m.closest, c.min_distance,
                held(3), ground, m.feasible() ? "feasible" : "not feasible");
  return text;
}

// AuRoRA's formations' flights (the UAV-UGV line, the triangle) as a table:
// its columns (the CSV's header: `step, t`, each robot's, Q_, Qd_), then one
// row of values per step, the step first. The flight tool writes it as CSV
// (csvTable), Python keeps it as an array: the same numbers. Either part
// may be empty (not wanted).
struct FlightTable {
  std::function<void(const std::vector<std::string>&)> columns;
  std::function<void(const std::vector<double>&)> row;
};

// The table as the CSV file `f` (none when null): the step as an integer,
// every other value as the shortest text that reads back to it (number_text.h).
inline FlightTable csvTable(FILE* f) {
  FlightTable t;
  if (!f) return t;
  t.columns = [f](const std::vector<std::string>& c) {
    for (size_t i = 0; i < c.size(); ++i) std::fprintf(f, "%s%s", i ? "," : "", c[i].c_str());
    std::fprintf(f, "\n");
  };
  t.row = [f](const std::vector<double>& v) {
    std::fprintf(f, "%ld", long(v[0]));
    for (size_t i = 1; i < v.size(); ++i) aurora_common::writeNumber(f, v[i]);
    std::fprintf(f, "\n");
  };
  return t;
}

// What a flight of AuRoRA's formations reports besides its rows: the line
// the tool prints and its errors by name (RMS after 20 s, closest approach).
struct ShapedFlight {
  std::string summary;
  std::vector<std::pair<std::string, double>> errors;
  double seconds = 0.0;  // wall time of the run
};

// The printed RMS errors are taken from this time on [s] (AuRoRA's reports).
constexpr double kRmsFrom = 20.0;

// The RMS line of a shaped flight: `values` when `samples` fell after
// kRmsFrom, else that the window is empty (a flight ending at `end_s`, a
// 15 s triangle say): an empty window is no 0 error. Its errors are then
// NaN (not measured).
inline std::string rmsLine(long samples, double end_s, const std::string& values, const std::string& rest) {
  const std::string measured = samples > 0 ? values : "none, the flight ends at " + YamlReader::fmt(end_s) + " s";
  return "  RMS after " + YamlReader::fmt(kRmsFrom) + " s: " + measured + "; " + rest + "\n";
}

// A UAV-UGV line's or a triangle's flight fills a FlightTable (its columns
// first, then a row per step): its entry's flyTable (shapes.h), defined
// in the shape's own flight file. Its tool form (the entry's fly) writes
// o.csv from it and prints the summary: flyShapedToCsv.
template <class Entry>
void flyShapedToCsv(const typename Entry::File& file, const FormationFlightOptions& o) {
  FILE* csv = o.csv.empty() ? nullptr : std::fopen(o.csv.c_str(), "w");
  if (!o.csv.empty() && !csv) throw std::runtime_error("cannot write '" + o.csv + "'");
  FlightTable table = csvTable(csv);
  ShapedFlight f;
  try {
    f = Entry::flyTable(file, o, table);
  } catch (...) {
    if (csv) std::fclose(csv), std::remove(o.csv.c_str());  // nothing half-written
    throw;
  }
  if (csv) std::fclose(csv);
  std::printf("%s", f.summary.c_str());
}

// Flies steps k = 0 .. steps - 1 (fly(k)), adding row(k) to the table when
// it wants rows; returns the wall time [s].
template <class Fly, class Row>
double flyTable(FlightTable& table, long steps, Fly&& fly, Row&& row) {
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < steps; ++k) {
    fly(k);
    if (table.row) table.row(row(k));
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace aurora_control
