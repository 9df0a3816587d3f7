#include "aurora_sweep/sweep_file.h"

#include <boost/algorithm/string/join.hpp>
#include <csv.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>

#include "aurora_control/link/link_yaml.h"
#include "aurora_control/loop/positioning_runner.h"
#include "aurora_control/predictor/predictor_yaml.h"
#include "aurora_control/task/task_yaml.h"
#include "aurora_sweep/backends.h"
#include "aurora_sweep/design.h"
#include "sweep_file_formation.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

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

bool fileExists(const std::string& path) { return std::ifstream(path).good(); }

std::string resolve(const std::string& name, const std::string& sweep_dir,
                    const std::string& config_dir) {
  if (!name.empty() && name[0] == '/') return name;
  if (fileExists(sweep_dir + "/" + name)) return sweep_dir + "/" + name;
  if (!config_dir.empty() && fileExists(config_dir + "/" + name)) return config_dir + "/" + name;
  return sweep_dir + "/" + name;
}

// What the accepted names are for: "the pd_saturated controller", "a formation sweep".
std::string sweepKind(const SweepSpec& spec) {
  return spec.formation() ? std::string("a formation sweep (its robots' delays, the formation's gains, the link's "
                                        "values, each robot's own law's gains)")
                          : "the " + spec.controller + " controller";
}

// A parameter named in the file, for the sweep's controller: its ParamId,
// or a refusal listing the names that controller accepts.
int paramOf(const Reader& r, const SweepSpec& spec, const std::string& name, const std::string& key) {
  const int id = spec.paramId(name);
  if (id < 0 || !spec.accepts(id)) {
    r.fail(key, "is not a parameter of " + sweepKind(spec) + ": accepted " + spec.acceptedNames());
  }
  return id;
}

// A value inside the parameter's accepted range (parameters.h), naming it.
void checkValue(const Reader& r, const SweepSpec& spec, int id, double v, const std::string& key) {
  const ParamInfo& p = spec.param(id);
  long samples = 0;
  if (p.group == ParamGroup::kDelay) {
    const std::string refusal = aurora_control::delayRefusal(v, false, 0.0, samples);
    if (!refusal.empty()) r.fail(key, "= " + Reader::fmt(v) + " " + refusal);
  } else if (!(v >= p.min && v <= p.max)) {
    r.fail(key, "= " + Reader::fmt(v) + " is outside the accepted range [" + Reader::fmt(p.min) + ", " +
                    Reader::fmt(p.max) + "] of " + p.name + " (" + p.limit + ")");
  } else if (p.whole && v != std::floor(v)) {
    r.fail(key, "= " + Reader::fmt(v) + " is refused: " + p.name + " takes whole samples");
  }
}

// A CSV file's rows of fields, through libcsv (RFC 4180: quoted fields, as
// pandas and Excel write them; spaces around fields trimmed). A UTF-8 byte
// order mark (Excel writes one) is skipped. Blank lines are no rows.
std::vector<std::vector<std::string>> readCsvRows(const Reader& r, const std::string& path, const std::string& key) {
  std::ifstream in(path, std::ios::binary);
  if (!in) r.fail(key, "names '" + path + "', which cannot be read");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  struct Rows {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> row;
  } rows;
  const auto field = [](void* s, size_t n, void* data) {
    static_cast<Rows*>(data)->row.emplace_back(static_cast<const char*>(s), n);
  };
  const auto row_end = [](int, void* data) {
    Rows& d = *static_cast<Rows*>(data);
    const bool blank = d.row.size() == 1 && d.row[0].empty();
    if (!blank) d.rows.push_back(d.row);
    d.row.clear();
  };
  csv_parser parser;
  csv_init(&parser, CSV_STRICT | CSV_STRICT_FINI);
  const bool parsed = csv_parse(&parser, text.data(), text.size(), field, row_end, &rows) == text.size() &&
                      csv_fini(&parser, field, row_end, &rows) == 0;
  const std::string problem = parsed ? "" : csv_strerror(csv_error(&parser));
  csv_free(&parser);
  if (!parsed) r.fail(key, "file '" + path + "' is not valid CSV (" + problem + ": a quote not closed?)");
  return rows.rows;
}

// The header of a points file: parameter names, each once.
std::vector<int> readPointsHeader(const Reader& r, const SweepSpec& spec, const std::vector<std::string>& header,
                                  const std::string& where) {
  std::vector<int> ids;
  for (const std::string& name : header) {
    const int id = paramOf(r, spec, name, where + " header column " + name);
    if (std::find(ids.begin(), ids.end(), id) != ids.end()) r.fail(where, "names column '" + name + "' twice");
    ids.push_back(id);
  }
  return ids;
}

// A points file: a header of parameter names, then one row of values per
// combination.
void readPoints(const Reader& r, const std::string& path, const std::string& key, SweepSpec& spec) {
  const std::vector<std::vector<std::string>> rows = readCsvRows(r, path, key);
  if (rows.empty()) r.fail(key, "file '" + path + "' is empty");
  const std::string where = key + " ('" + path + "')";
  spec.point_params = readPointsHeader(r, spec, rows[0], where);
  const size_t cols = spec.point_params.size();
  for (size_t row = 1; row < rows.size(); ++row) {
    const std::string at = where + " row " + std::to_string(row + 1);
    if (rows[row].size() != cols) {
      r.fail(at, "has " + std::to_string(rows[row].size()) + " columns: the header has " + std::to_string(cols));
    }
    for (size_t col = 0; col < cols; ++col) {
      const std::string& cell = rows[row][col];
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || !std::isfinite(v)) r.fail(at, "'" + cell + "' is not a number");
      checkValue(r, spec, spec.point_params[col], v, at + " " + spec.paramNameOf(spec.point_params[col]));
      spec.points.push_back(v);
    }
  }
  if (spec.points.empty()) r.fail(key, "file '" + path + "' has no points");
}

// sweep.task: a task file's name (e.g. tasks/positioning.yaml) or the task
// inline, in the one task schema (aurora_control/task/task_yaml.h).
// The heights the sweep's vehicle accepts in a task (a ground robot's: the floor).
aurora_control::TaskHeights taskHeightsOf(const SweepSpec& spec) {
  aurora_control::TaskHeights h = aurora_control::TaskHeights::flying();
  withSweepLaw(spec, [&](auto law) { h = aurora_control::TaskHeights::of<typename decltype(law)::Vehicle>(); });
  return h;
}

void readSweepTask(const Reader& r, const YAML::Node& t, const std::string& sweep_dir,
                   const std::string& config_dir, SweepSpec& spec) {
  aurora_control::Task<double> task;
  if (t.IsScalar()) {
    const std::string path = resolve(r.text(t, "sweep.task"), sweep_dir, config_dir);
    YAML::Node file;
    try {
      file = aurora_common::loadYamlFile("task file", path);
    } catch (const aurora_common::ConfigError& e) {
      r.fail("sweep.task", "names a file that is refused: " + std::string(e.what()));
    }
    const aurora_control::YamlReader tr("task file '" + path + "': ");
    task = aurora_control::readTask(tr, file["task"], "task", taskHeightsOf(spec));
  } else {
    task = aurora_control::readTask(r, t, "sweep.task", taskHeightsOf(spec));
  }
  spec.task = task;
  if (!(spec.duration() <= 3600)) {
    r.fail("sweep.task", "lasts " + Reader::fmt(spec.duration()) + " s: accepted up to 3600 s per simulation");
  }
}

}  // namespace

namespace {

// {from, to[, scale]} of one parameter: a non-empty range inside the
// parameter's accepted values; scale linear (default) or log (from > 0).
SampledRange readRange(const Reader& r, const SweepSpec& spec, const YAML::Node& v, const std::string& key, int id) {
  SampledRange range;
  range.from = r.number(v["from"], key + ".from");
  range.to = r.number(v["to"], key + ".to");
  range.integer = spec.param(id).whole;
  if (range.to < range.from) {
    r.fail(key, "is an empty range: 'to' (" + Reader::fmt(range.to) + ") is below 'from' (" +
                    Reader::fmt(range.from) + ")");
  }
  checkValue(r, spec, id, range.from, key + ".from");
  checkValue(r, spec, id, range.to, key + ".to");
  if (v["scale"]) {
    const std::string scale = r.text(v["scale"], key + ".scale");
    if (scale != "linear" && scale != "log") r.fail(key + ".scale", "= '" + scale + "': accepted linear, log");
    range.log = scale == "log";
    if (range.log && range.integer) r.fail(key + ".scale", std::string("= log: ") + spec.paramNameOf(id) + " takes whole samples, scale linear");
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

// A value of parameter `id`: a number, or its shape's law by its name
// (formation_law: one of its entry's sweepLawNames, the triangle's N, PSO,
// SPO, OSP, S-PO; its index there as its value).
double valueOf(const Reader& r, const SweepSpec& spec, int id, const YAML::Node& v, const std::string& key) {
  if (spec.param(id).group != ParamGroup::kFormationLaw) return r.number(v, key);
  double index = 0.0;
  if (v.IsScalar() && YAML::convert<double>::decode(v, index)) return index;
  const std::string name = r.text(v, key);
  const std::vector<std::string> laws = formationLawNames(spec.shape);
  const auto at = std::find(laws.begin(), laws.end(), name);
  if (at == laws.end()) {
    r.failWith(key + " = '" + name + "' is not a " + sweepShapeName(spec.shape) + " law: accepted " +
               boost::algorithm::join(laws, ", "));
  }
  return double(at - laws.begin());
}

// Values of one grid axis: {values: [...]} or {from, to, count[, scale]}.
std::vector<double> readAxisValues(const Reader& r, const SweepSpec& spec, const YAML::Node& v, const std::string& key, int id) {
  std::vector<double> values;
  if (v["values"]) {
    r.onlyKeys(v, key, {"values"});
    if (!v["values"].IsSequence() || v["values"].size() == 0) r.fail(key + ".values", "is empty: give at least one value");
    for (const auto& x : v["values"]) values.push_back(valueOf(r, spec, id, x, key + ".values"));
    for (double x : values) checkValue(r, spec, id, x, key);
    return values;
  }
  r.onlyKeys(v, key, {"from", "to", "count", "scale"});
  if (!v["from"] || !v["to"] || !v["count"]) r.fail(key, "needs from, to and count (or values: [...])");
  const SampledRange range = readRange(r, spec, v, key, id);
  const long count = r.integer(v["count"], key + ".count");
  if (count < 1) r.fail(key + ".count", "= " + std::to_string(count) + " is below 1: accepted counts >= 1");
  if (count == 1 && range.from != range.to) r.fail(key, "has count 1 but from != to: an empty range");
  // Linear: from + (i (to - from)) / (count - 1), so kp = i 0.75 / 31 has
  // the bits of the thesis grid; log: from (to / from)^(i / (count - 1)).
  for (long i = 0; i < count; ++i) {
    const double t = count == 1 ? 0.0 : double(i) / double(count - 1);
    values.push_back(count == 1 ? range.from
                     : range.log ? range.at(t)
                                 : range.from + (double(i) * (range.to - range.from)) / double(count - 1));
  }
  for (double x : values) checkValue(r, spec, id, x, key);
  return values;
}

// sweep.parameters: each entry fixes a value, or varies the parameter (a
// grid axis, or a design's range {from, to[, scale]}; `points` given: only
// fixed values). Returns the varied parameters' axes (grid) or ranges
// (design), in ParamId order.
struct Varied {
  std::vector<Axis> axes;
  std::vector<int> sampled;
  std::vector<SampledRange> ranges;
};

Varied readParameters(const Reader& r, const YAML::Node& params, bool design, bool points, SweepSpec& spec) {
  if (!params.IsMap()) r.fail("sweep.parameters", "must be a mapping of parameter names: accepted " +
                                                      spec.acceptedNames());
  std::map<int, YAML::Node> entries;
  for (const auto& kv : params) {
    const std::string name = kv.first.as<std::string>();
    entries[paramOf(r, spec, name, "sweep.parameters." + name)] = kv.second;
  }
  Varied varied;
  for (const auto& e : entries) {
    const int id = e.first;
    const std::string key = std::string("sweep.parameters.") + spec.paramNameOf(id);
    const YAML::Node& v = e.second;
    if (v.IsScalar()) {
      spec.fixed[id] = valueOf(r, spec, id, v, key);
      checkValue(r, spec, id, spec.fixed[id], key);
    } else if (points) {
      r.fail(key, "is a range, but 'points' lists the combinations: with points, parameters only fix values");
    } else if (!v.IsMap()) {
      r.fail(key, "must be a value, {from, to, count} or {values: [...]}");
    } else if (design) {
      if (v["values"] || v["count"]) r.fail(key, "must be a value or a range {from, to[, scale]}: a " + spec.design + " design samples ranges");
      r.onlyKeys(v, key, {"from", "to", "scale"});
      if (!v["from"] || !v["to"]) r.fail(key, "needs from and to");
      varied.sampled.push_back(id);
      varied.ranges.push_back(readRange(r, spec, v, key, id));
    } else {
      varied.axes.push_back(Axis{static_cast<ParamId>(id), readAxisValues(r, spec, v, key, id)});
    }
  }
  return varied;
}

// The design's samples as points: the varied parameters' columns.
void sampleDesign(const Reader& r, const Varied& varied, SweepSpec& spec) {
  if (varied.sampled.empty()) r.fail("sweep.parameters", "vary none: a design needs at least one range");
  Design design = Design::kGrid;
  designFromName(spec.design, design);
  const int dims = static_cast<int>(varied.sampled.size());
  const std::vector<double> u = unitSamples(design, spec.samples, dims, spec.seed);
  spec.point_params = varied.sampled;
  spec.points.resize(u.size());
  for (size_t i = 0; i < u.size(); ++i) spec.points[i] = varied.ranges[i % dims].at(u[i]);
}

// sweep.order: the grid's axes, first varying fastest (default: ParamId order).
void orderAxes(const Reader& r, const YAML::Node& s, std::vector<Axis> axes, SweepSpec& spec) {
  if (!s["order"]) {
    spec.axes = axes;
    return;
  }
  if (!s["order"].IsSequence()) r.fail("sweep.order", "must be a list of the varied parameters");
  std::vector<int> order;
  for (const auto& o : s["order"]) {
    const int id = paramOf(r, spec, r.text(o, "sweep.order"), "sweep.order");
    if (std::find(order.begin(), order.end(), id) != order.end()) r.fail("sweep.order", std::string("names '") + spec.paramNameOf(id) + "' twice");
    order.push_back(id);
  }
  // A fixed parameter in the order is accepted: it does not vary, so its
  // place does not matter (e.g. 'delay: 600' with the usual order).
  std::vector<std::string> names;
  for (const Axis& a : axes) names.push_back(spec.paramNameOf(a.param));
  for (int id : order) {
    for (const Axis& a : axes) {
      if (a.param == id) spec.axes.push_back(a);
    }
  }
  if (spec.axes.size() != axes.size()) {
    r.fail("sweep.order", "must list every varied parameter (" + joinKeys(names) + "), first varying fastest");
  }
}

// Every parameter the law needs has a value: given, varied or a default.
void requireAll(const Reader& r, const SweepSpec& spec) {
  for (int id = 0; id < kParamCount; ++id) {
    // A formation's link values and robot gains: NaN keeps each robot's own.
    const ParamGroup group = spec.param(id).group;
    const bool own = spec.formation() && (group == ParamGroup::kLink || group == ParamGroup::kDroneLink ||
                                          group == ParamGroup::kRobotGain);
    if (spec.accepts(id) && !own && std::isnan(spec.fixed[id]) && !spec.varies(id)) {
      r.fail(std::string("sweep.parameters.") + spec.paramNameOf(id), "is missing: the " + spec.controller +
                 " controller has no default for it; give a value or a range (or a points column)");
    }
  }
}

// sweep.criteria: the thresholds of checks 1-4 and the metrics' dt.
void readCriteria(const Reader& r, const YAML::Node& c, aurora_control::FeasibilityCriteria<double>& cr) {
  r.onlyKeys(c, "sweep.criteria", {"max_error", "max_iae", "max_itae", "error_growth", "metric_dt"});
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

// sweep.early_stop, clamp_commands and precision.
void readRunOptions(const Reader& r, const YAML::Node& s, SweepSpec& spec) {
  if (s["early_stop"]) spec.early_stop = r.boolean(s["early_stop"], "sweep.early_stop");
  if (s["clamp_commands"]) spec.clamp_commands = r.boolean(s["clamp_commands"], "sweep.clamp_commands");
  if (s["precision"]) {
    const std::string p = r.text(s["precision"], "sweep.precision");
    if (p == "double") spec.precision = Precision::kDouble;
    else if (p == "float") spec.precision = Precision::kFloat;
    else r.fail("sweep.precision", "= '" + p + "' is not accepted: 'double' or 'float'");
  }
}

// The combinations: a points file, a sampling design or a grid of axes; then
// every parameter has a value, and the largest delay is known.
void readCombinations(const Reader& r, const YAML::Node& s, const std::string& sweep_dir,
                      const std::string& config_dir, SweepSpec& spec) {
  const bool has_points = static_cast<bool>(s["points"]);
  if (has_points && s["order"]) r.fail("sweep.order", "is for grids: a points file lists the combinations in its order");
  const bool design = readDesign(r, s, spec);
  if (has_points && design) r.fail("sweep.points", "excludes a sampling design: give one or the other");
  const YAML::Node params = s["parameters"];
  if (!params && !has_points) {
    r.fail("sweep.parameters", "is missing: give each parameter a value or a range (accepted " +
                                   spec.acceptedNames() + "), or 'points'");
  }
  const Varied varied = params ? readParameters(r, params, design, has_points, spec) : Varied();
  if (has_points) {
    spec.points_file = resolve(r.text(s["points"], "sweep.points"), sweep_dir, config_dir);
    readPoints(r, spec.points_file, "sweep.points", spec);
    for (int id : spec.point_params) {
      if (params && params[spec.paramNameOf(id)]) {
        r.fail(std::string("sweep.parameters.") + spec.paramNameOf(id), "is also a column of the points file: give it once");
      }
    }
  } else if (design) {
    sampleDesign(r, varied, spec);
  } else {
    orderAxes(r, s, varied.axes, spec);
  }
  const size_t varying = spec.axes.size() + spec.point_params.size();
  if (varying > static_cast<size_t>(kMaxVaried)) {
    r.fail(has_points ? "sweep.points" : "sweep.parameters",
           "varies " + std::to_string(varying) + " parameters: at most " + std::to_string(kMaxVaried) +
               " vary in one sweep; fix the others to one value");
  }
  requireAll(r, spec);
  std::vector<int> delays{kParamDelay};
  if (spec.formation()) {
    delays.clear();
    for (int d = 0; d < spec.layout().robots; ++d) delays.push_back(spec.layout().delay(d));
  }
  spec.max_delay = 0;
  for (int id : delays) {
    spec.max_delay = std::max(spec.max_delay, static_cast<long>(spec.maxValue(id)));
    // A design's delay range counts whole, whichever samples it happened to draw.
    for (size_t j = 0; j < varied.sampled.size(); ++j) {
      if (varied.sampled[j] == id) spec.max_delay = std::max(spec.max_delay, static_cast<long>(varied.ranges[j].to));
    }
  }
}

// sweep.link: a link file (docs/links.md) for every combination; each
// combination's delay replaces the file's uplink delay, the link values the
// sweep file gives or varies replace the file's (read before the parameters).
void readSweepLink(const Reader& r, const YAML::Node& node, const std::string& sweep_dir,
                   const std::string& config_dir, SweepSpec& spec) {
  spec.link_file = resolve(r.text(node, "sweep.link"), sweep_dir, config_dir);
  try {
    spec.setLink(aurora_control::readLinkFile(spec.link_file));
  } catch (const aurora_common::ConfigError& e) {
    r.fail("sweep.link", "names a link file that is refused: " + std::string(e.what()));
  }
}

// sweep.repeats: runs of each combination, each with its own link seed.
void readRepeats(const Reader& r, const YAML::Node& node, SweepSpec& spec) {
  spec.repeats = r.integer(node, "sweep.repeats");
  if (spec.repeats < 1 || spec.repeats > kMaxRepeats) {
    r.fail("sweep.repeats", "= " + std::to_string(spec.repeats) + " is refused: accepted [1, " +
                                std::to_string(kMaxRepeats) + "] runs of each combination");
  }
}

// The link of every combination, once the parameters are read: `link` takes
// the fixed values; the burst's bound on the loss holds for the largest
// loss with the smallest burst above 1 of each direction; the history holds
// the largest delay plus jitter; repeats draw something.
void checkSweepLink(const Reader& r, SweepSpec& spec) {
  if (spec.formation()) return checkFormationLinks(r, spec);
  for (int i = 0; i < kLinkParamCount; ++i) aurora_control::setLinkValue(spec.link, i, spec.fixed[kParamFirstLinkValue + i]);
  for (const int loss_value : {aurora_control::kLinkUplinkLoss, aurora_control::kLinkDownlinkLoss}) {
    const int loss = kParamFirstLinkValue + loss_value, burst = loss + 1;
    aurora_control::LinkDirection worst;
    worst.loss = spec.maxValue(loss);
    worst.burst = 1e300;
    spec.forEachValue(burst, [&](double b) { worst.burst = b > 1.0 && b < worst.burst ? b : worst.burst; });
    const std::string refusal = aurora_control::burstLossRefusal(worst);
    if (worst.burst < 1e300 && !refusal.empty()) {
      r.fail(std::string("sweep.parameters.") + spec.paramNameOf(loss), "= " + Reader::fmt(worst.loss) + " (its largest) " +
                 refusal + " (" + spec.paramNameOf(burst) + "'s smallest above 1)");
    }
  }
  if (spec.historyNeeded() > aurora_control::kMaxDelaySamples) {
    r.fail(spec.link_file.empty() ? "sweep.parameters" : "sweep.link",
           "needs " + std::to_string(spec.historyNeeded()) + " samples of history (the largest delay " +
               std::to_string(spec.max_delay) + " plus the link's jitter): accepted up to " +
               std::to_string(aurora_control::kMaxDelaySamples));
  }
  bool draws = false;  // some jitter or loss, on some combination
  for (int i : {aurora_control::kLinkUplinkJitter, aurora_control::kLinkUplinkLoss, aurora_control::kLinkDownlinkJitter,
                aurora_control::kLinkDownlinkLoss}) {
    draws = draws || spec.maxValue(kParamFirstLinkValue + i) > 0.0;
  }
  if (spec.repeats > 1 && !draws) {
    r.fail("sweep.repeats", "= " + std::to_string(spec.repeats) + " draws nothing: without jitter or loss on "
           "either direction every repeat is the same run; give a link with jitter or loss (sweep.link or the link "
           "parameters), or remove repeats");
  }
}

// sweep.controller (a law's name: it chooses the vehicle) and sweep.vehicle
// (default: that vehicle's shipped file), of the type the law flies.
void readSweepVehicle(const Reader& r, const YAML::Node& s, const std::string& sweep_dir,
                      const std::string& config_dir, SweepSpec& spec) {
  if (s["controller"]) spec.controller = r.text(s["controller"], "sweep.controller");
  if (!aurora_control::isKnownLawName(spec.controller)) {
    r.fail("sweep.controller", "= '" + spec.controller + "' is not a known controller: accepted " +
                                   aurora_control::knownLawNames("'"));
  }
  withSweepLaw(spec, [&](auto law) {
    using Vehicle = typename decltype(law)::Vehicle;
    spec.vehicle_type = Vehicle::name();
    const std::string vehicle = s["vehicle"] ? r.text(s["vehicle"], "sweep.vehicle")
                                             : "vehicles/" + spec.vehicle_type + ".yaml";
    spec.vehicle_file = resolve(vehicle, sweep_dir, config_dir);
    spec.paramsOf(Vehicle()) =
        aurora_sim::loadVehicleFile<Vehicle>(spec.vehicle_file, "the sweep's controller '" + spec.controller + "'");
  });
}

// sweep.predictor (docs/predictor.md, "In a sweep"): {form, model}, the
// model a vehicle file of the law's vehicle (default: the sweep's).
void readSweepPredictor(const Reader& r, const YAML::Node& n, const std::string& sweep_dir,
                        const std::string& config_dir, SweepSpec& spec) {
  r.onlyKeys(n, "sweep.predictor", {"form", "model"});
  spec.predictor = aurora_control::predictorFormNamed(
      r, r.require(n, "sweep.predictor", "form", "resimulate, smith, off"), "sweep.predictor.form");
  if (spec.predicting() && spec.formation()) {
    r.fail("sweep.predictor", "is refused for a formation sweep: its robots fly the predictor their controller files "
                              "give (the formation file's, e.g. controller: controllers/underactuated_predictor.yaml; "
                              "docs/predictor.md)");
  }
  spec.predictor_model_file =
      n["model"] ? resolve(r.text(n["model"], "sweep.predictor.model"), sweep_dir, config_dir) : spec.vehicle_file;
  withSweepLaw(spec, [&](auto law) {
    aurora_sim::loadVehicleFile<typename decltype(law)::Vehicle>(
        spec.predictor_model_file, "the predictor (sweep.predictor.model) of the sweep's controller '" +
                                       spec.controller + "'");
  });
}

SweepSpec parseSweepFile(const std::string& path, const std::string& config_dir) {
  Reader r(path);
  const YAML::Node root = aurora_common::loadYamlFile("sweep file", path);
  r.onlyKeys(root, "", {"sweep"});
  const YAML::Node s = root["sweep"];
  if (!s) r.fail("sweep", "is missing: the file's top level must be 'sweep:'");
  r.onlyKeys(s, "sweep", {"name", "controller", "vehicle", "task", "formation", "parameters", "order", "points",
                          "criteria", "early_stop", "clamp_commands", "precision", "design", "samples",
                          "seed", "link", "repeats", "predictor"});
  SweepSpec spec;
  spec.file = path;
  const std::string sweep_dir = aurora_common::folderOf(path);
  spec.name = s["name"] ? r.text(s["name"], "sweep.name") : "sweep";

  readSweepVehicle(r, s, sweep_dir, config_dir, spec);

  if (s["formation"]) {
    const std::string file = resolve(r.text(s["formation"], "sweep.formation"), sweep_dir, config_dir);
    readSweepFormation(r, s, file, config_dir, spec);
  }
  if (s["predictor"]) readSweepPredictor(r, s["predictor"], sweep_dir, config_dir, spec);
  if (s["task"]) readSweepTask(r, s["task"], sweep_dir, config_dir, spec);
  if (!s["task"] && !spec.formation() && !taskHeightsOf(spec).accepts(spec.task.at(0.0).pos[2])) {
    r.fail("sweep.task", "is missing: the default task (the thesis's positioning, at " +
                             Reader::fmt(spec.task.at(0.0).pos[2]) + " m) is not one a " + spec.vehicle_type +
                             " can fly: give a task (accepted heights " + taskHeightsOf(spec).rangeText() + ")");
  }

  if (s["criteria"] && spec.formation()) readFormationCriteria(r, s["criteria"], spec.formation_criteria);
  if (spec.formation() && !(spec.formation_duration > spec.formation_criteria.settle_time)) {
    // The formation file's own rule (formation_file.h, shortFormationRefusal) with the sweep's settle time.
    r.fail("sweep.criteria.settle_time", "= " + Reader::fmt(spec.formation_criteria.settle_time) +
                                             " s is refused: the formation file '" + spec.formation_file + "' flies " +
                                             Reader::fmt(spec.formation_duration) + " s, and checks from the settle time "
                                             "on would judge nothing (every error 0, feasible); accepted settle times "
                                             "below " + Reader::fmt(spec.formation_duration) + " s");
  }
  if (s["criteria"] && !spec.formation()) readCriteria(r, s["criteria"], spec.criteria);
  readRunOptions(r, s, spec);

  if (s["link"]) readSweepLink(r, s["link"], sweep_dir, config_dir, spec);
  if (s["repeats"]) readRepeats(r, s["repeats"], spec);
  readCombinations(r, s, sweep_dir, config_dir, spec);
  checkSweepLink(r, spec);
  return spec;
}

}  // namespace

SweepSpec loadSweepFile(const std::string& path, const std::string& config_dir) {
  SweepSpec spec = parseSweepFile(path, config_dir);
  const long iterations = spec.iterations();
  if (!aurora_control::delayShorterThanRun(spec.max_delay, iterations)) {
    Reader(path).fail(!spec.points_file.empty() ? "sweep.points" : spec.formation() ? "sweep.parameters" : "sweep.parameters.delay",
                      "= " + aurora_control::delayRunText(spec.max_delay, iterations,
                                                                           spec.Ts()));
  }
  // The largest delay plus the link's jitter (or its command path), as flight and the node refuse it.
  const long latest = spec.historyNeeded();
  if (!aurora_control::delayShorterThanRun(latest, iterations)) {
    Reader(path).fail(spec.link_file.empty() ? "sweep.parameters" : "sweep.link",
                      "gives packets that would never arrive: the latest (the largest delay plus the jitter, or the "
                      "command path) is " + aurora_control::delayRunText(latest, iterations, spec.Ts()));
  }
  return spec;
}

}  // namespace aurora_sweep
