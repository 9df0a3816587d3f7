#include "aurora_sweep/sweep_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "aurora_control/positioning_runner.h"
#include "aurora_control/task_yaml.h"
#include "aurora_sweep/design.h"
#include "aurora_sim/vehicle_yaml.h"

namespace aurora_sweep {

namespace {

using aurora_control::joinKeys;

// The shared strict reader, with the sweep file named in every message.
class Reader : public aurora_control::YamlReader {
 public:
  explicit Reader(std::string file) : YamlReader("sweep file '" + file + "': "), file_(std::move(file)) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

std::string dirOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

bool fileExists(const std::string& path) { return std::ifstream(path).good(); }

std::string resolve(const std::string& name, const std::string& sweep_dir,
                    const std::string& config_dir) {
  if (!name.empty() && name[0] == '/') return name;
  if (fileExists(sweep_dir + "/" + name)) return sweep_dir + "/" + name;
  if (!config_dir.empty() && fileExists(config_dir + "/" + name)) return config_dir + "/" + name;
  return sweep_dir + "/" + name;
}

int paramIdOf(const std::string& name) {
  if (name == "kp") return kParamKp;
  if (name == "kd") return kParamKd;
  if (name == "delay") return kParamDelay;
  return -1;
}

void checkValue(const Reader& r, int id, double v, const std::string& key) {
  if (id == kParamDelay) {
    if (v != std::floor(v) || v < 0 || v > aurora_control::kMaxRunnerDelay) {
      r.fail(key, "= " + std::to_string(v) + " is not a delay: accepted whole samples in [0, " +
                      std::to_string(aurora_control::kMaxRunnerDelay) + "]");
    }
  } else if (v < aurora_control::kPdGainMin || v > aurora_control::kPdGainMax) {
    r.fail(key, "= " + Reader::fmt(v) + " is outside the accepted range [" + Reader::fmt(aurora_control::kPdGainMin) +
                    ", " + Reader::fmt(aurora_control::kPdGainMax) + "] (the controller node's)");
  }
}

std::vector<double> readPoints(const Reader& r, const std::string& path, const std::string& key) {
  std::ifstream in(path);
  if (!in) r.fail(key, "names '" + path + "', which cannot be read");
  std::string line;
  if (!std::getline(in, line)) r.fail(key, "file '" + path + "' is empty");
  std::string header;
  for (char c : line) {
    if (c != ' ' && c != '\r') header += c;
  }
  if (header != "kp,kd,delay") {
    r.fail(key, "file '" + path + "' must start with the header 'kp,kd,delay', found '" + line + "'");
  }
  std::vector<double> points;
  long row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.find_first_not_of(" \r\t") == std::string::npos) continue;
    std::stringstream ss(line);
    std::string cell;
    int col = 0;
    while (std::getline(ss, cell, ',')) {
      if (col >= 3) r.fail(key, "file '" + path + "' row " + std::to_string(row) + " has more than 3 columns");
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      if (end == cell.c_str() || !std::isfinite(v)) {
        r.fail(key, "file '" + path + "' row " + std::to_string(row) + ": '" + cell + "' is not a number");
      }
      checkValue(r, col, v, key + " (" + path + " row " + std::to_string(row) + ", " + paramName(col) + ")");
      points.push_back(v);
      ++col;
    }
    if (col != 3) r.fail(key, "file '" + path + "' row " + std::to_string(row) + " needs 3 columns kp,kd,delay");
  }
  if (points.empty()) r.fail(key, "file '" + path + "' has no points");
  return points;
}

// sweep.task: a task file's name (e.g. tasks/positioning.yaml) or the task
// inline, in the one task schema (aurora_control/task_yaml.h).
void readSweepTask(const Reader& r, const YAML::Node& t, const std::string& sweep_dir,
                   const std::string& config_dir, SweepSpec& spec) {
  aurora_control::Task<double> task;
  if (t.IsScalar()) {
    const std::string path = resolve(r.text(t, "sweep.task"), sweep_dir, config_dir);
    YAML::Node file;
    try {
      file = YAML::LoadFile(path);
    } catch (const YAML::Exception& e) {
      r.fail("sweep.task", "names '" + path + "', which cannot be read: " + e.what());
    }
    const aurora_control::YamlReader tr("task file '" + path + "': ");
    task = aurora_control::readTask(tr, file["task"], "task");
  } else {
    task = aurora_control::readTask(r, t, "sweep.task");
  }
  if (task.type != aurora_control::TaskType::kWaypoints || task.waypoints.count != 1) {
    r.fail("sweep.task", "is a " + std::string(task.isTrajectory() ? "trajectory" : "multi-waypoint") +
                             " task: the sweep's engines fly single-point positioning tasks (one waypoint) "
                             "so far; the study's task is tasks/positioning.yaml");
  }
  for (int i = 0; i < 3; ++i) spec.desired[i] = task.waypoints.position[0][i];
  spec.duration = task.waypoints.duration;
  if (!(spec.duration <= 3600)) r.fail("sweep.task.duration", "is outside the accepted range (0, 3600] s");
}

}  // namespace

aurora_sim::ArdroneParams<double> loadVehicleFile(const std::string& path) {
  try {
    return aurora_sim::loadVehicleYaml(path);
  } catch (const std::runtime_error& e) {
    throw SweepFileError(e.what());
  }
}

namespace {

// {from, to[, scale]} of one parameter: a non-empty range inside the
// parameter's accepted values; scale linear (default) or log (from > 0).
SampledRange readRange(const Reader& r, const YAML::Node& v, const std::string& key, int id) {
  SampledRange range;
  range.from = r.number(v["from"], key + ".from");
  range.to = r.number(v["to"], key + ".to");
  range.integer = id == kParamDelay;
  if (range.to < range.from) {
    r.fail(key, "is an empty range: 'to' (" + Reader::fmt(range.to) + ") is below 'from' (" +
                    Reader::fmt(range.from) + ")");
  }
  checkValue(r, id, range.from, key + ".from");
  checkValue(r, id, range.to, key + ".to");
  if (v["scale"]) {
    const std::string scale = r.text(v["scale"], key + ".scale");
    if (scale != "linear" && scale != "log") r.fail(key + ".scale", "= '" + scale + "': accepted linear, log");
    range.log = scale == "log";
    if (range.log && range.integer) r.fail(key + ".scale", "= log: a delay takes whole samples, scale linear");
    if (range.log && !(range.from > 0)) r.fail(key + ".scale", "= log needs 'from' > 0");
  }
  return range;
}

// sweep.design (default grid), with samples and seed for the others.
bool readDesign(const Reader& r, const YAML::Node& s, SweepSpec& spec) {
  Design design = Design::kGrid;
  if (s["design"]) {
    spec.design = r.text(s["design"], "sweep.design");
    if (!designFromName(spec.design, design)) {
      r.fail("sweep.design", "= '" + spec.design + "' is unknown: accepted grid, random, latin_hypercube, sobol");
    }
  }
  if (design == Design::kGrid) {
    if (s["samples"] || s["seed"]) r.fail(s["samples"] ? "sweep.samples" : "sweep.seed", "is for sampling designs: "
                                          "give design: random, latin_hypercube or sobol, or remove it");
    return false;
  }
  if (!s["samples"]) r.fail("sweep.samples", "is missing: a " + spec.design + " design needs the number of samples");
  spec.samples = r.integer(s["samples"], "sweep.samples");
  if (spec.samples < 1 || spec.samples > (1L << 31)) r.fail("sweep.samples", "is outside the accepted range [1, 2^31]");
  const long seed = s["seed"] ? r.integer(s["seed"], "sweep.seed") : 0;
  if (seed < 0) r.fail("sweep.seed", "must be >= 0");
  spec.seed = static_cast<unsigned long long>(seed);
  if (s["order"]) r.fail("sweep.order", "is for grids: a " + spec.design + " design has no axes to order");
  return true;
}

// The design's samples as points (kp, kd, delay): varied parameters from
// their ranges, the others fixed.
void sampleDesign(const Reader& r, const YAML::Node& params, SweepSpec& spec) {
  r.onlyKeys(params, "sweep.parameters", {"kp", "kd", "delay"});
  std::vector<int> varied;
  std::vector<SampledRange> ranges;
  for (int id = 0; id < kParamCount; ++id) {
    const std::string key = std::string("sweep.parameters.") + paramName(id);
    const YAML::Node v = params[paramName(id)];
    if (!v) r.fail(key, "is missing: give a value or a range for each of kp, kd, delay");
    if (v.IsScalar()) {
      spec.fixed[id] = r.number(v, key);
      checkValue(r, id, spec.fixed[id], key);
      continue;
    }
    if (!v.IsMap() || v["values"] || v["count"]) {
      r.fail(key, "must be a value or a range {from, to[, scale]}: a " + spec.design + " design samples ranges");
    }
    r.onlyKeys(v, key, {"from", "to", "scale"});
    if (!v["from"] || !v["to"]) r.fail(key, "needs from and to");
    varied.push_back(id);
    ranges.push_back(readRange(r, v, key, id));
  }
  if (varied.empty()) r.fail("sweep.parameters", "vary none: a design needs at least one range");
  Design design = Design::kGrid;
  designFromName(spec.design, design);
  const int dims = static_cast<int>(varied.size());
  const std::vector<double> u = unitSamples(design, spec.samples, dims, spec.seed);
  spec.points.resize(static_cast<size_t>(spec.samples) * kParamCount);
  for (long i = 0; i < spec.samples; ++i) {
    double* p = &spec.points[static_cast<size_t>(i) * kParamCount];
    for (int id = 0; id < kParamCount; ++id) p[id] = spec.fixed[id];
    for (int j = 0; j < dims; ++j) p[varied[j]] = ranges[j].at(u[static_cast<size_t>(i) * dims + j]);
    spec.max_delay = std::max(spec.max_delay, static_cast<long>(p[kParamDelay]));
  }
}

SweepSpec parseSweepFile(const std::string& path, const std::string& config_dir) {
  Reader r(path);
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw SweepFileError("sweep file '" + path + "' cannot be read (does it exist?)");
  } catch (const YAML::Exception& e) {
    throw SweepFileError("sweep file '" + path + "' is not valid YAML: " + e.what());
  }
  r.onlyKeys(root, "", {"sweep"});
  const YAML::Node s = root["sweep"];
  if (!s) r.fail("sweep", "is missing: the file's top level must be 'sweep:'");
  r.onlyKeys(s, "sweep", {"name", "controller", "vehicle", "task", "parameters", "order", "points",
                          "criteria", "early_stop", "clamp_commands", "precision", "design", "samples",
                          "seed"});
  SweepSpec spec;
  spec.file = path;
  const std::string sweep_dir = dirOf(path);
  spec.name = s["name"] ? r.text(s["name"], "sweep.name") : "sweep";

  if (s["controller"]) {
    spec.controller = r.text(s["controller"], "sweep.controller");
    if (spec.controller != "pd_saturated") {
      r.fail("sweep.controller", "= '" + spec.controller +
                                     "' is not a known controller: accepted 'pd_saturated'");
    }
  }
  const std::string vehicle = s["vehicle"] ? r.text(s["vehicle"], "sweep.vehicle")
                                           : std::string("vehicles/ardrone2.yaml");
  spec.vehicle_file = resolve(vehicle, sweep_dir, config_dir);
  spec.vehicle = loadVehicleFile(spec.vehicle_file);

  if (s["task"]) readSweepTask(r, s["task"], sweep_dir, config_dir, spec);

  if (s["criteria"]) {
    const YAML::Node c = s["criteria"];
    r.onlyKeys(c, "sweep.criteria", {"max_error", "max_iae", "max_itae", "error_growth", "metric_dt"});
    auto& cr = spec.criteria;
    if (c["max_error"]) cr.max_error = r.threshold(c["max_error"], "sweep.criteria.max_error");
    if (c["max_iae"]) cr.max_iae = r.threshold(c["max_iae"], "sweep.criteria.max_iae");
    if (c["max_itae"]) cr.max_itae = r.threshold(c["max_itae"], "sweep.criteria.max_itae");
    if (c["error_growth"]) cr.error_growth = r.threshold(c["error_growth"], "sweep.criteria.error_growth");
    if (c["metric_dt"]) cr.metric_dt = r.number(c["metric_dt"], "sweep.criteria.metric_dt");
    const double all[] = {cr.max_error, cr.max_iae, cr.max_itae, cr.error_growth, cr.metric_dt};
    const char* names[] = {"max_error", "max_iae", "max_itae", "error_growth", "metric_dt"};
    for (int i = 0; i < 5; ++i) {
      if (!(all[i] > 0)) r.fail(std::string("sweep.criteria.") + names[i], "must be > 0");
    }
  }

  if (s["early_stop"]) spec.early_stop = r.boolean(s["early_stop"], "sweep.early_stop");
  if (s["clamp_commands"]) spec.clamp_commands = r.boolean(s["clamp_commands"], "sweep.clamp_commands");
  if (s["precision"]) {
    const std::string p = r.text(s["precision"], "sweep.precision");
    if (p == "double") spec.precision = Precision::kDouble;
    else if (p == "float") spec.precision = Precision::kFloat;
    else r.fail("sweep.precision", "= '" + p + "' is not accepted: 'double' or 'float'");
  }

  const bool has_points = static_cast<bool>(s["points"]);
  if (has_points) {
    if (s["parameters"] || s["order"]) {
      r.fail("sweep.points", "excludes 'parameters' and 'order': a sweep is either a grid or a points file");
    }
    spec.points_file = resolve(r.text(s["points"], "sweep.points"), sweep_dir, config_dir);
    spec.points = readPoints(r, spec.points_file, "sweep.points");
    for (size_t i = 2; i < spec.points.size(); i += 3) {
      spec.max_delay = std::max(spec.max_delay, static_cast<long>(spec.points[i]));
    }
    return spec;
  }

  const YAML::Node params = s["parameters"];
  if (!params) r.fail("sweep.parameters", "is missing: give kp, kd and delay (a value or a range), or 'points'");
  if (readDesign(r, s, spec)) {
    sampleDesign(r, params, spec);
    return spec;
  }
  r.onlyKeys(params, "sweep.parameters", {"kp", "kd", "delay"});
  std::vector<std::string> varied;
  bool given[kParamCount] = {false, false, false};
  std::vector<Axis> axes_by_name;
  for (const auto& kv : params) {
    const std::string name = kv.first.as<std::string>();
    const int id = paramIdOf(name);
    const std::string key = "sweep.parameters." + name;
    given[id] = true;
    const YAML::Node v = kv.second;
    if (v.IsScalar()) {
      spec.fixed[id] = r.number(v, key);
      checkValue(r, id, spec.fixed[id], key);
      continue;
    }
    Axis axis{static_cast<ParamId>(id), {}};
    if (v.IsMap() && v["values"]) {
      r.onlyKeys(v, key, {"values"});
      if (!v["values"].IsSequence() || v["values"].size() == 0) {
        r.fail(key + ".values", "is empty: give at least one value");
      }
      for (const auto& x : v["values"]) axis.values.push_back(r.number(x, key + ".values"));
    } else if (v.IsMap()) {
      r.onlyKeys(v, key, {"from", "to", "count", "scale"});
      if (!v["from"] || !v["to"] || !v["count"]) r.fail(key, "needs from, to and count (or values: [...])");
      const SampledRange range = readRange(r, v, key, id);
      const long count = r.integer(v["count"], key + ".count");
      if (count < 1) r.fail(key + ".count", "= " + std::to_string(count) + " is below 1: accepted counts >= 1");
      if (count == 1 && range.from != range.to) r.fail(key, "has count 1 but from != to: an empty range");
      // Linear: from + (i (to - from)) / (count - 1), so kp = i 0.75 / 31 has
      // the bits of the thesis grid; log: from (to / from)^(i / (count - 1)).
      for (long i = 0; i < count; ++i) {
        const double t = count == 1 ? 0.0 : double(i) / double(count - 1);
        axis.values.push_back(count == 1 ? range.from
                              : range.log ? range.at(t)
                                          : range.from + (double(i) * (range.to - range.from)) / double(count - 1));
      }
    } else {
      r.fail(key, "must be a value, {from, to, count} or {values: [...]}");
    }
    for (double x : axis.values) checkValue(r, id, x, key);
    varied.push_back(name);
    axes_by_name.push_back(axis);
  }
  for (int id = 0; id < kParamCount; ++id) {
    if (!given[id]) {
      r.fail(std::string("sweep.parameters.") + paramName(id),
             "is missing: give a value or a range for each of kp, kd, delay");
    }
  }
  std::vector<std::string> order;
  if (s["order"]) {
    if (!s["order"].IsSequence()) r.fail("sweep.order", "must be a list of the varied parameters");
    for (const auto& o : s["order"]) order.push_back(r.text(o, "sweep.order"));
    std::set<std::string> seen;
    for (const auto& o : order) {
      if (paramIdOf(o) < 0) r.fail("sweep.order", "names unknown parameter '" + o + "': accepted kp, kd, delay");
      if (!seen.insert(o).second) r.fail("sweep.order", "names '" + o + "' twice");
    }
    // A fixed parameter in the order is accepted: it does not vary, so its
    // place does not matter (e.g. 'delay: 600' with the usual order).
    order.erase(std::remove_if(order.begin(), order.end(), [&](const std::string& o) {
                  return std::find(varied.begin(), varied.end(), o) == varied.end();
                }), order.end());
    if (order.size() != varied.size()) {
      r.fail("sweep.order", "must list every varied parameter (" + joinKeys(varied) + "), first varying fastest");
    }
  } else {
    for (const char* n : {"kp", "kd", "delay"}) {
      if (std::find(varied.begin(), varied.end(), n) != varied.end()) order.push_back(n);
    }
  }
  for (const auto& o : order) {
    for (const auto& a : axes_by_name) {
      if (a.param == paramIdOf(o)) spec.axes.push_back(a);
    }
  }
  spec.max_delay = static_cast<long>(spec.fixed[kParamDelay]);
  for (const auto& a : spec.axes) {
    if (a.param == kParamDelay) {
      spec.max_delay = static_cast<long>(*std::max_element(a.values.begin(), a.values.end()));
    }
  }
  return spec;
}

}  // namespace

SweepSpec loadSweepFile(const std::string& path, const std::string& config_dir) {
  SweepSpec spec = parseSweepFile(path, config_dir);
  const long iterations = aurora_control::studyIterationCount(spec.duration, spec.vehicle.Ts);
  if (!aurora_control::delayShorterThanRun(spec.max_delay, iterations)) {
    Reader(path).fail(spec.points.empty() ? "sweep.parameters.delay" : "sweep.points",
                      "= " + aurora_control::delayRunText(spec.max_delay, iterations,
                                                                           spec.vehicle.Ts));
  }
  return spec;
}

}  // namespace aurora_sweep
