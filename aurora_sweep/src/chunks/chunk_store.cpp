#include "aurora_sweep/chunk_store.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <boost/crc.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace aurora_sweep {

namespace {

// A chunk file: this header, then `count` SimResult records.
struct ChunkHeader {
  char magic[8];          // "AURCHNK2"
  uint32_t hash;          // definitionHash of the sweep
  uint32_t record_size;   // sizeof(SimResult)
  int64_t begin, count;   // combinations [begin, begin + count)
  char computed_by[64];   // the backend (and device) that computed it, zero-padded
};
constexpr char kMagic[8] = {'A', 'U', 'R', 'C', 'H', 'N', 'K', '2'};

class Crc {
 public:
  template <typename V>
  void add(const V& v) {
    crc_.process_bytes(&v, sizeof v);
  }
  void add(const std::string& s) {
    add(s.size());
    crc_.process_bytes(s.data(), s.size());
  }
  void add(const std::vector<double>& v) {
    add(v.size());
    crc_.process_bytes(v.data(), v.size() * sizeof(double));
  }
  uint32_t value() const { return crc_.checksum(); }

 private:
  boost::crc_32_type crc_;
};

bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

// A string field of a finished run's summary.json ("" if none or unreadable).
std::string summaryField(const std::string& path, const char* field) {
  std::ifstream in(path);
  if (!in) return "";
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);  // no throw: discarded if damaged
  const bool has = summary.is_object() && summary.contains(field) && summary[field].is_string();
  return has ? summary[field].get<std::string>() : "";
}

// progress/definition: "HASH TOTAL CHUNK", then "computed_by ...", then
// "sweep NAME" (for the messages).
struct Definition {
  std::string line, computed_by, name;
};

Definition readDefinition(const std::string& path) {
  Definition d;
  std::ifstream in(path);
  std::getline(in, d.line);
  std::string l;
  while (std::getline(in, l)) {
    if (l.rfind("computed_by ", 0) == 0) d.computed_by = l.substr(12);
    if (l.rfind("sweep ", 0) == 0) d.name = l.substr(6);
  }
  return d;
}

void removeFile(const std::string& path) {
  if (std::remove(path.c_str()) != 0 && errno != ENOENT) {
    throw std::runtime_error("cannot remove '" + path + "': " + std::strerror(errno));
  }
}

// The task's defining values only (a waypoint task leaves the trajectory's
// fields unset).
void addTask(Crc& crc, const aurora_control::Task<double>& task) {
  crc.add(static_cast<int>(task.type));
  if (task.isTrajectory()) {
    const auto& t = task.trajectory;
    crc.add(static_cast<int>(t.kind));
    for (double v : {t.centre[0], t.centre[1], t.centre[2], t.size[0], t.size[1], t.period, t.yaw}) crc.add(v);
    crc.add(t.laps);
    crc.add(t.yaw_along_path);
    if (t.fast_x) crc.add(t.fast_x);  // only when set: the hashes of tasks that predate it stay
    return;
  }
  const auto& w = task.waypoints;
  crc.add(w.count);
  for (int i = 0; i < w.count; ++i) {
    for (int j = 0; j < 3; ++j) crc.add(w.position[i][j]);
    crc.add(w.end_time[i]);
    if (w.yaw[i] != 0.0) crc.add(w.yaw[i]);  // only when set: the hashes of tasks that predate it stay
  }
  crc.add(w.duration);
}

}  // namespace

namespace {

// Field by field: the struct's padding is not part of the definition.
void addLink(Crc& crc, const aurora_control::LinkParams& l) {
  for (const aurora_control::LinkDirection* d : {&l.uplink, &l.downlink}) {
    crc.add(d->delay), crc.add(static_cast<int>(d->jitter)), crc.add(d->jitter_max), crc.add(d->jitter_mean);
    crc.add(d->loss), crc.add(d->burst);
  }
  crc.add(l.seed), crc.add(l.cmd_timeout);
}

}  // namespace

namespace {

// Another vehicle's sweep (an AR.Drone sweep's hash stays as it was): its
// type, its vehicle file's values and its law's own gains.
void addOtherVehicle(Crc& crc, const SweepSpec& spec) {
  crc.add(spec.vehicle_type);
  const auto add = [&](const auto& params) {
    static_assert(sizeof(params) % sizeof(double) == 0, "vehicle constants are doubles");
    crc.add(params);
  };
  spec.vehicles.withType(spec.vehicle_type, add);
  forEachLawGainParam([&](int id) {
    if (spec.accepts(id)) crc.add(id), crc.add(spec.fixed[id]);
  });
}

}  // namespace

namespace {

// The formation's robots' predictors (only theirs that fly one: the hashes
// of formations without stay): form, horizon and model values.
void addFormationPredictors(Crc& crc, const SweepSpec& spec) {
  spec.withFormation([&](const auto& run, auto) {
    for (int d = 0; d < spec.layout().robots; ++d) {
      const auto& p = run.drone[d].predictor;
      if (!p.on()) continue;
      crc.add(d), crc.add(std::string(aurora_control::predictorFormName(p.form))), crc.add(p.path.horizon);
      crc.add(p.model);
    }
  });
}

// The predictor's form and its model's file as it is (its values).
void addPredictor(Crc& crc, const SweepSpec& spec) {
  crc.add(std::string(aurora_control::predictorFormName(spec.predictor)));
  std::ifstream f(spec.predictor_model_file);
  crc.add(std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()));
}

}  // namespace

uint32_t definitionHash(const SweepSpec& spec) {
  static_assert(sizeof(spec.defaultVehicle()) % sizeof(double) == 0, "vehicle constants are doubles");
  Crc crc;
  crc.add(std::string("aurora_sweep definition v2"));
  crc.add(spec.controller);
  crc.add(spec.defaultVehicle());  // every sweep's, as before the other vehicles (older hashes stay)
  addTask(crc, spec.task);
  crc.add(spec.criteria);
  for (const Axis& a : spec.axes) {
    crc.add(static_cast<int>(a.param));
    crc.add(a.values);
  }
  for (int id = 0; id < kParamCountBeforeLinks; ++id) crc.add(spec.fixed[id]);
  crc.add(spec.points);
  for (int p : spec.point_params) crc.add(p);
  crc.add(spec.early_stop);
  crc.add(spec.clamp_commands);
  crc.add(static_cast<int>(spec.precision));
  if (!spec.linkIdeal() || spec.repeats > 1) {  // an ideal link keeps the hashes of the sweeps before links
    addLink(crc, spec.link);
    for (int id = kParamCountBeforeLinks; id < kParamCountBeforeDroneLinks; ++id) crc.add(spec.fixed[id]);
    crc.add(spec.repeats);
  }
  if (spec.formation()) {  // the formation file's text, the formation's criteria and parameters
    std::ifstream f(spec.formation_file);
    crc.add(std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()));
    crc.add(spec.formation_criteria);
    const ShapeLayout at = spec.layout();  // the line's: 31 .. 45, then its robots' links (older hashes stay)
    for (int id = at.delay(0); id < at.linkValue(0, 0); ++id) crc.add(spec.fixed[id]);
    for (int id = at.linkValue(0, 0); id < at.count(); ++id) {  // only those given: older hashes stay
      if (spec.given(id)) crc.add(id), crc.add(spec.fixed[id]);
    }
    if (spec.variesFormationLaw()) crc.add(spec.fixed[kParamFormationLaw]);
    addFormationPredictors(crc, spec);
    for (int id = kParamFirstRobotGain; id < kParamRobotGainEnd; ++id) {  // the robots' gains it gives (older hashes stay)
      if (spec.given(id)) crc.add(id), crc.add(spec.fixed[id]);
    }
  }
  if (spec.vehicle_type != aurora_sim::DefaultVehicle::name()) addOtherVehicle(crc, spec);
  if (spec.predicting()) addPredictor(crc, spec);  // only with one: the hashes of sweeps without stay
  return crc.value();
}

std::string hashText(uint32_t hash) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08x", hash);
  return buf;
}

const std::vector<std::string>& sweepOutputFiles() {
  static const std::vector<std::string> files{
      "results.csv", "results.h5", "summary.json", "feasible_volume.png", "feasible_marginals.png",
      "feasible_pairs.png", "max_tolerable_delay.png", "check1_region.png",
      "check2_region.png", "check3_region.png", "check4_region.png", "feasible_share.csv", "feasible_share.png", "formation_delays.png", "formation_law_delays.png"};
  return files;
}

ChunkStore::ChunkStore(const std::string& out_dir, const SweepSpec& spec, const ChunkPlan& plan,
                       bool overwrite, const std::string& computed_by)
    : out_dir_(out_dir), progress_dir_(out_dir + "/progress"), name_(spec.name), computed_by_(computed_by),
      chunk_by_(computed_by), plan_(plan), hash_(definitionHash(spec)) {
  openOrCreate(overwrite);
}

void ChunkStore::openOrCreate(bool overwrite) {
  const std::string definition = progress_dir_ + "/definition";
  // "HASH TOTAL CHUNK": another line is another definition, or this one in other chunks.
  const std::string mine = hashText(hash_) + " " + std::to_string(plan_.total) + " " +
                           std::to_string(plan_.size);
  std::string other;
  if (exists(definition)) {
    const Definition theirs = readDefinition(definition);
    if (theirs.line == mine && theirs.computed_by == computed_by_) {
      resumed_ = true;
      return;
    }
    if (theirs.line == mine && !overwrite && !theirs.computed_by.empty()) {
      throw std::runtime_error("'" + out_dir_ + "' holds this sweep in progress, computed so far by the " +
                               theirs.computed_by + " backend: resuming with " + computed_by_ +
                               " would mix numbers that differ in the last bits; resume with --backend " +
                               theirs.computed_by.substr(0, theirs.computed_by.find(' ')) +
                               " (and the same SIMD build), or give --overwrite to start again");
    }
    other = theirs.computed_by.empty()
                ? "progress of an earlier version of this program, whose chunk files it cannot read: " + theirs.line
                : "'" + theirs.name + "', in progress: hash, combinations, chunk size " + theirs.line;
  } else {
    const std::string summary = out_dir_ + "/summary.json";
    const std::string finished = summaryField(summary, "definition_hash");
    if (!finished.empty() && finished != hashText(hash_)) {
      other = "'" + summaryField(summary, "name") + "', finished: hash " + finished;
    }
  }
  if (!other.empty() && !overwrite) {
    throw std::runtime_error("'" + out_dir_ + "' holds another sweep (" + other + "; this one: '" + name_ +
                             "', " + mine + "): choose another --out, or give --overwrite to replace it");
  }
  // A fresh run: nothing of an earlier one may stay beside the new results.
  for (const std::string& f : sweepOutputFiles()) removeFile(out_dir_ + "/" + f);
  removeProgress();
  if (mkdir(progress_dir_.c_str(), 0755) != 0) {
    throw std::runtime_error("cannot create '" + progress_dir_ + "': " + std::strerror(errno));
  }
  std::ofstream(definition) << mine << "\ncomputed_by " << computed_by_ << "\nsweep " << name_ << "\n";
}

std::string ChunkStore::chunkPath(long chunk) const {
  char name[32];
  std::snprintf(name, sizeof name, "/chunk_%08ld.bin", chunk);
  return progress_dir_ + name;
}

bool ChunkStore::done(long chunk) const { return exists(chunkPath(chunk)); }

long ChunkStore::doneCount() const {
  long n = 0;
  for (long c = 0; c < plan_.count(); ++c) n += done(c);
  return n;
}

long ChunkStore::doneCombinations() const {
  long n = 0;
  for (long c = 0; c < plan_.count(); ++c) n += done(c) ? plan_.end(c) - plan_.begin(c) : 0;
  return n;
}

void ChunkStore::write(long chunk, const std::vector<SimResult>& results) const {
  ChunkHeader h;
  std::memset(&h, 0, sizeof h);  // every byte defined: chunk files are reproducible
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  std::strncpy(h.computed_by, chunk_by_.c_str(), sizeof h.computed_by - 1);
  h.hash = hash_;
  h.record_size = sizeof(SimResult);
  h.begin = plan_.begin(chunk);
  h.count = plan_.end(chunk) - plan_.begin(chunk);
  if (static_cast<int64_t>(results.size()) != h.count) {
    throw std::logic_error("chunk " + std::to_string(chunk) + ": " + std::to_string(results.size()) +
                           " results for " + std::to_string(h.count) + " combinations");
  }
  const std::string path = chunkPath(chunk), tmp = path + ".tmp." + std::to_string(getpid());
  FILE* f = std::fopen(tmp.c_str(), "wb");
  bool ok = f && std::fwrite(&h, sizeof h, 1, f) == 1 &&
            std::fwrite(results.data(), sizeof(SimResult), results.size(), f) == results.size();
  ok = f && std::fflush(f) == 0 && fsync(fileno(f)) == 0 && ok;
  if (f) ok = std::fclose(f) == 0 && ok;
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  }
}

void ChunkStore::read(long chunk, std::vector<SimResult>& results, std::string* computed_by) const {
  const std::string path = chunkPath(chunk);
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
  ChunkHeader h;
  const long expected = plan_.end(chunk) - plan_.begin(chunk);
  bool ok = std::fread(&h, sizeof h, 1, f) == 1 && std::memcmp(h.magic, kMagic, sizeof kMagic) == 0 &&
            h.hash == hash_ && h.record_size == sizeof(SimResult) && h.begin == plan_.begin(chunk) &&
            h.count == expected;
  if (ok) {
    results.resize(static_cast<size_t>(expected));
    ok = std::fread(results.data(), sizeof(SimResult), results.size(), f) == results.size();
  }
  std::fclose(f);
  if (!ok) {
    throw std::runtime_error("chunk file '" + path + "' is damaged or of another sweep: delete it and run "
                             "the same command again (it is recomputed)");
  }
  if (computed_by) *computed_by = std::string(h.computed_by, strnlen(h.computed_by, sizeof h.computed_by));
}

void ChunkStore::removeProgress() const {
  DIR* d = opendir(progress_dir_.c_str());
  if (!d) return;
  while (dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    if (name != "." && name != "..") removeFile(progress_dir_ + "/" + name);
  }
  closedir(d);
  rmdir(progress_dir_.c_str());
}

}  // namespace aurora_sweep
