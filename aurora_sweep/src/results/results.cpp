#include "aurora_sweep/results.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "aurora_common/number_text.h"
#include "aurora_sweep/chunk_store.h"
#include "aurora_sweep/result_columns.h"

namespace aurora_sweep {

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The summary's predictor: the sweep's {form, model}; a formation's robots'
// forms, one per robot (their controller files'); or "off".
nlohmann::json predictorJson(const SweepSpec& spec) {
  using nlohmann::json;
  if (spec.predicting()) {
    return json{{"form", aurora_control::predictorFormName(spec.predictor)}, {"model", spec.predictor_model_file}};
  }
  if (!spec.formationPredicting()) return json("off");
  json robots = json::array();
  spec.withFormation([&](const auto& run, auto) {
    for (int d = 0; d < spec.layout().robots; ++d) robots.push_back(aurora_control::predictorFormName(run.drone[d].predictor.form));
  });
  return json{{"robots", robots}};
}

// One CSV row per combination, in index order.
class CsvWriter : public ResultsWriter {
 public:
  CsvWriter(const std::string& path, const SweepSpec& spec, bool feasible_only)
      : path_(path), grid_(spec.view()), params_(spec.columns()), results_(resultColumns(spec.formation())),
        feasible_only_(feasible_only) {
    f_ = std::fopen(path.c_str(), "w");
    if (!f_) throw std::runtime_error("cannot write '" + path + "'");
    std::fprintf(f_, "index");
    for (int id : params_) std::fprintf(f_, ",%s", spec.paramNameOf(id));
    for (int k = 0; k < results_.count; ++k) std::fprintf(f_, ",%s", results_[k].name);
    std::fprintf(f_, "\n");
  }
  ~CsvWriter() override {
    if (f_) std::fclose(f_);
  }
  void append(long first, const std::vector<SimResult>& results) override {
    for (size_t i = 0; i < results.size(); ++i) {
      const SimResult& r = results[i];
      if (feasible_only_ && !feasible(r)) continue;
      const long index = first + static_cast<long>(i);
      const Combination c = grid_.decode(index);
      std::fprintf(f_, "%ld", index);
      for (int id : params_) {
        if (id == kParamDelay) std::fprintf(f_, ",%ld", c.delay());
        else aurora_common::writeNumber(f_, c.v[id]);
      }
      for (int k = 0; k < results_.count; ++k) print(columnValue(r, results_[k]));
      std::fprintf(f_, "\n");
      ++rows_;
    }
  }
  void close() override {
    FILE* f = f_;
    f_ = nullptr;
    if (std::fclose(f) != 0) throw std::runtime_error("cannot finish writing '" + path_ + "'");
  }
  long rows() const override { return rows_; }

 private:
  // Doubles and floats as the shortest text that reads back to the same
  // value (number_text.h: 0.85, not 0.84999999999999998).
  void print(const ColumnValue& v) {
    switch (v.type) {
      case ColumnType::kFlag: std::fprintf(f_, ",%d", v.flag); break;
      case ColumnType::kDouble: aurora_common::writeNumber(f_, v.real); break;
      case ColumnType::kInt32: std::fprintf(f_, ",%d", v.whole); break;
      case ColumnType::kFloat: aurora_common::writeNumber(f_, v.single); break;
    }
  }

  std::string path_;
  GridView grid_;
  std::vector<int> params_;  // ParamIds of the parameter columns
  ResultColumnList results_;  // then these
  bool feasible_only_;
  FILE* f_ = nullptr;
  long rows_ = 0;
};

}  // namespace

DelayMonotony::DelayMonotony(const SweepSpec& spec) : grid_(spec.view()) {
  // Applies to grids of exactly the axes delay and two of the law's gains, one run each.
  if (!spec.points.empty() || spec.axes.size() != 3 || spec.repeats > 1) return;
  int gains = 0;
  for (const Axis& a : spec.axes) {
    const ParamGroup g = spec.param(a.param).group;
    const bool gain = g == ParamGroup::kLawGain;
    if (a.param != kParamDelay && !gain) return;
    std::vector<double>& v = a.param == kParamDelay ? delays_ : values_[gains];
    if (a.param != kParamDelay) gain_[gains++] = a.param;
    v = a.values;
    std::sort(v.begin(), v.end());  // a `values:` list may come in any order
  }
  if (gains != 2) return;
  if (gain_[0] == kParamKd && gain_[1] == kParamKp) std::swap(gain_[0], gain_[1]), std::swap(values_[0], values_[1]);
  applies_ = true;
  feasible_.assign(values_[0].size() * values_[1].size() * delays_.size(), 0);
}

void DelayMonotony::add(long first, const std::vector<SimResult>& results) {
  if (!applies_) return;
  const auto at = [](const std::vector<double>& v, double x) {
    return static_cast<size_t>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
  };
  for (size_t i = 0; i < results.size(); ++i) {
    const Combination c = grid_.decode(first + static_cast<long>(i));
    const size_t pair = at(values_[0], c.v[gain_[0]]) * values_[1].size() + at(values_[1], c.v[gain_[1]]);
    feasible_[pair * delays_.size() + at(delays_, c.v[kParamDelay])] = feasible(results[i]);
  }
}

long DelayMonotony::nonMonotonePairs() const {
  long count = 0;
  const size_t n = delays_.size();
  for (size_t p = 0; p + n <= feasible_.size(); p += n) {
    bool failed = false, again = false;
    for (size_t d = 0; d < n; ++d) {
      again = again || (failed && feasible_[p + d]);
      failed = failed || !feasible_[p + d];
    }
    count += again;
  }
  return count;
}

FeasibleShare::FeasibleShare(const SweepSpec& spec) : repeats_(spec.repeats) {
  if (applies()) feasible_runs_.assign(static_cast<size_t>(spec.combinations()), 0);
}

void FeasibleShare::add(long first, const std::vector<SimResult>& results) {
  if (!applies()) return;
  for (size_t i = 0; i < results.size(); ++i) {
    feasible_runs_[static_cast<size_t>((first + static_cast<long>(i)) / repeats_)] += feasible(results[i]);
  }
}

nlohmann::json FeasibleShare::summary() const {
  std::vector<long> by_runs(static_cast<size_t>(repeats_) + 1, 0);
  double share = 0;
  for (unsigned int n : feasible_runs_) ++by_runs[n], share += double(n) / double(repeats_);
  return {{"repeats", repeats_},
          {"combinations", feasible_runs_.size()},
          {"combinations_by_feasible_runs", by_runs},
          {"mean_share", feasible_runs_.empty() ? 0.0 : share / double(feasible_runs_.size())}};
}

void FeasibleShare::writeCsv(const std::string& path, const SweepSpec& spec) const {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write '" + path + "'");
  std::vector<int> params = spec.columns();
  params.erase(std::remove(params.begin(), params.end(), int(kParamRepeat)), params.end());
  std::fprintf(f, "combination");
  for (int id : params) std::fprintf(f, ",%s", spec.paramNameOf(id));
  std::fprintf(f, ",repeats,feasible_runs,feasible_share\n");
  const GridView grid = spec.view();
  for (size_t k = 0; k < feasible_runs_.size(); ++k) {
    const Combination c = grid.decode(static_cast<long>(k) * repeats_);
    std::fprintf(f, "%zu", k);
    for (int id : params) aurora_common::writeNumber(f, c.v[id]);
    std::fprintf(f, ",%ld,%u", repeats_, feasible_runs_[k]);
    aurora_common::writeNumber(f, double(feasible_runs_[k]) / double(repeats_));
    std::fprintf(f, "\n");
  }
  if (std::fclose(f) != 0) throw std::runtime_error("cannot finish writing '" + path + "'");
}

void addCounts(Counts& c, const std::vector<SimResult>& results, long iterations) {
  c.combinations += static_cast<long>(results.size());
  for (const SimResult& r : results) {
    const bool complete = r.steps >= iterations;
    for (int i = 0; i < c.checks; ++i) {
      const bool held = checkHeld(r, i);
      c.passed[i] += held && complete;
      c.failed[i] += !held;
      c.not_reached[i] += held && !complete;
    }
    c.feasible += feasible(r);
    c.steps += r.steps;
  }
}

Counts countResults(const std::vector<SimResult>& results, long iterations, int checks) {
  Counts c(checks);
  addCounts(c, results, iterations);
  return c;
}

std::unique_ptr<ResultsWriter> openCsvWriter(const std::string& path, const SweepSpec& spec,
                                             bool feasible_only) {
  return std::unique_ptr<ResultsWriter>(new CsvWriter(path, spec, feasible_only));
}

void writeResultsCsv(const std::string& path, const SweepSpec& spec,
                     const std::vector<SimResult>& results) {
  const std::unique_ptr<ResultsWriter> w = openCsvWriter(path, spec, false);
  w->append(0, results);
  w->close();
}

namespace {

// result_columns.h as JSON: what plot_sweep and other readers go by.
nlohmann::json resultColumnsJson(bool formation) {
  const char* types[] = {"flag", "double", "int32", "float"};
  nlohmann::json columns = nlohmann::json::array();
  const ResultColumnList list = resultColumns(formation);
  for (int k = 0; k < list.count; ++k) {
    const ResultColumn& c = list[k];
    columns.push_back({{"name", c.name}, {"type", types[static_cast<int>(c.type)]}, {"unit", c.unit},
                       {"doc", c.doc}});
  }
  return columns;
}

}  // namespace

void writeSummaryJson(const std::string& path, const SweepSpec& spec, const RunInfo& info,
                      const Counts& counts, const nlohmann::json& extra) {
  using nlohmann::json;
  const double sims = info.computed_combinations >= 0 ? info.computed_combinations : counts.combinations;
  const double steps = info.computed_steps >= 0 ? info.computed_steps : counts.steps;
  const double sims_per_s = info.wall_time_s > 0 ? sims / info.wall_time_s : 0;
  const double steps_per_s = info.wall_time_s > 0 ? steps / info.wall_time_s : 0;
  json order = json::array();
  for (const Axis& a : spec.axes) order.push_back(spec.paramNameOf(a.param));
  // The result rows' parameter columns, and the values of those not varied.
  json parameters = json::array(), fixed = json::object(), factors = json::array();
  for (int id : spec.columns()) {
    parameters.push_back(spec.paramNameOf(id));
    if (!spec.varies(id)) fixed[spec.paramNameOf(id)] = spec.fixed[id];
    if (spec.param(id).group == ParamGroup::kModelFactor) factors.push_back(spec.paramNameOf(id));
  }
  const auto list = [&](const long* v) { return json(std::vector<long>(v, v + counts.checks)); };
  json j = {
      {"name", spec.name},
      {"sweep_file", spec.file},
      {"sweep_file_text", readFile(spec.file)},
      {"definition_hash", hashText(definitionHash(spec))},
      {"vehicle_file", spec.vehicle_file},
      {"vehicle_type", spec.vehicle_type},
      {"controller", spec.controller},
      {"predictor", predictorJson(spec)},
      {"parameters", parameters},
      {"model_factors", factors},  // those of `parameters` that scale the vehicle file's values
      {"result_columns", resultColumnsJson(spec.formation())},
      {"link", spec.linkIdeal() ? json("ideal") : spec.link_file.empty() ? json("the link parameters") : json(spec.link_file)},
      {"repeats", spec.repeats},
      {"fixed", fixed},
      {"task_duration_s", spec.duration()},
      {"sample_time_s", spec.formation() ? spec.formationTs() : spec.Ts()},  // a delay sample [s]
      {"order", order},
      {"combinations", counts.combinations},
      {"feasible", counts.feasible},
      // Per check (1-4; a formation sweep 1-5): held through a complete run / failed / not reached
      // (the run stopped early at another check's failure while this one held).
      {"checks", {{"passed", list(counts.passed)}, {"failed", list(counts.failed)},
                  {"not_reached", list(counts.not_reached)}}},
      {"control_steps", counts.steps},
      {"early_stop", spec.early_stop},
      {"clamp_commands", spec.clamp_commands},
      {"backend", info.backend},
      {"device", info.device},
      {"precision", precisionName(spec.precision)},
      {"threads", info.threads},
      {"lanes", info.lanes},
      {"wall_time_s", info.wall_time_s},
      {"total_time_s", info.wall_time_s},
      {"simulations_per_s", sims_per_s},
      {"control_steps_per_s", steps_per_s},
      {"note", info.note},
  };
  if (spec.formation()) {
    const auto& c = spec.formation_criteria;
    j["formation_file"] = spec.formation_file;
    j["formation_shape"] = sweepShapeName(spec.shape);  // line, uav_ugv_line, triangle
    if (spec.variesFormationLaw()) j["formation_laws"] = formationLawNames(spec.shape);  // formation_law's names
    j["formation_criteria"] = {{"settle_time", c.settle_time}, {"max_position_error", c.max_position_error},
                               {"max_shape_error", c.max_shape_error}, {"max_iae_position", c.max_iae_position},
                               {"max_iae_shape", c.max_iae_shape}, {"min_distance", c.min_distance},
                               {"max_ground_speed", c.max_ground_speed},
                               {"max_ground_turn_rate", c.max_ground_turn_rate}};
  }
  if (!spec.points_file.empty()) j["points_file"] = spec.points_file;
  j["design"] = spec.design;
  if (spec.design != "grid") j["design_samples"] = {{"samples", spec.samples}, {"seed", spec.seed}};
  if (info.kernel_time_s >= 0) j["kernel_time_s"] = info.kernel_time_s;
  for (auto it = extra.begin(); it != extra.end(); ++it) j[it.key()] = it.value();
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write '" + path + "'");
  f << j.dump(2) << "\n";
  if (!f) throw std::runtime_error("cannot finish writing '" + path + "'");
}

}  // namespace aurora_sweep
