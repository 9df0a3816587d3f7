// sweep: runs a grid search, a sampling design or a list of points over a
// law's gains, the delay and the model's parameters, and tells which
// combinations fly safely.
//   rosrun aurora_sweep sweep --config FILE --out DIR [--backend scalar|cpu|cuda|auto]
//                             [--precision double|float] [--threads N] [--no-plots] [--rviz]
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <memory>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "aurora_common/ros/config_dir.h"
#include "aurora_sweep/backends.h"
#include "aurora_sweep/cuda_backend.h"
#include "aurora_sweep/recent_rate.h"
#include "aurora_sweep/results.h"
#include "aurora_sweep/rviz_markers.h"
#include "aurora_sweep/sweep_file.h"
#include "../chunks/chunk_runner.h"
#include "../chunks/mpi_ranks.h"
#include "sweep_plan.h"
#include "sweep_start.h"

namespace {

using namespace aurora_sweep;

// plot_sweep is installed beside this program (devel space: catkin's relay;
// install space: the script), so it is found without a source path.
std::string besideThisProgram(const std::string& name) {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return name;  // looked up on PATH
  std::string dir(self, static_cast<size_t>(n));
  return dir.substr(0, dir.rfind('/') + 1) + name;
}

// Runs `program` with `args` and waits: no shell, so a folder name holding
// quotes or $(...) is passed as it is. Returns its exit status (-1: not run).
int runProgram(const std::string& program, const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Prints progress with an ETA to stderr once a second while `total` runs.
class ProgressMonitor {
 public:
  ProgressMonitor(const Progress& progress, long total, bool quiet)
      : progress_(progress), total_(total), quiet_(quiet), start_(Clock::now()),
        recent_(10.0, progress.load()) {
    if (!quiet_) thread_ = std::thread([this] { loop(); });
  }
  ~ProgressMonitor() { stop(); }
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

 private:
  using Clock = std::chrono::steady_clock;
  void loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!cv_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; })) {
      const long done = progress_.load(std::memory_order_relaxed);
      const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
      const double rate = recent_.add(elapsed, done);  // the last 10 s, not since the start
      const double eta = rate > 0 ? (total_ - done) / rate : 0.0;
      std::fprintf(stderr, "sweep: %ld/%ld (%.1f%%) %.0f sims/s, ETA %.0f s\n", done, total_,
                   100.0 * done / std::max(total_, 1L), rate, eta);
    }
  }
  const Progress& progress_;
  const long total_;
  const bool quiet_;
  const Clock::time_point start_;
  RecentRate recent_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

struct Outputs {
  std::vector<std::unique_ptr<ResultsWriter>> writers;
  std::vector<std::string> files, temporary;  // temporary: written for the plots only
};

Outputs openOutputs(const Options& opt, const SweepSpec& spec) {
  Outputs o;
  const std::string format = outputFormat(opt, spec.size());
  const bool feasible_only = opt.rows == "feasible";
  const bool h5 = format == "hdf5" || format == "both", csv = format == "csv" || format == "both";
  if (csv) o.files.push_back("results.csv");
  if (h5) o.files.push_back("results.h5");
  if (format == "none" && opt.plots) {  // the plots read a results file: a temporary one
    o.files.push_back(hdf5Available() ? "results.h5" : "results.csv");
    o.temporary.push_back(o.files.back());
  }
  for (const std::string& f : o.files) {
    const std::string path = opt.out + "/" + f;
    o.writers.push_back(f == "results.h5" ? openHdf5Writer(path, spec, feasible_only)
                                          : openCsvWriter(path, spec, feasible_only));
  }
  return o;
}

// Rows, seconds and rows per second of each results file written.
nlohmann::json runFacts(const Options& opt, const ChunkStore& store, const ChunkWork& work,
                        const Outputs& out, const std::vector<double>& writer_s, double merge_s) {
  nlohmann::json written = nlohmann::json::object();
  for (size_t i = 0; i < out.files.size(); ++i) {
    if (std::find(out.temporary.begin(), out.temporary.end(), out.files[i]) != out.temporary.end()) continue;
    const long rows = out.writers[i]->rows();
    written[out.files[i]] = {{"rows", rows}, {"write_s", writer_s[i]},
                             {"rows_per_s", writer_s[i] > 0 ? rows / writer_s[i] : 0.0}};
  }
  return {{"chunks", {{"size", store.plan().size}, {"count", store.plan().count()},
                      {"resumed", work.resumed_chunks}, {"computed", work.computed_chunks},
                      {"computed_combinations", work.computed_combinations}}},
          {"output", {{"rows", opt.rows}, {"files", written}, {"merge_s", merge_s}}},
          {"timing", {{"compute_s", work.compute_s}, {"chunk_write_s", work.write_s}}}};
}

// "a b c d" of a count per check.
std::string perCheck(const Counts& counts, const long* v) {
  std::string s;
  for (int i = 0; i < counts.checks; ++i) s += (i ? " " : "") + std::to_string(v[i]);
  return s;
}

void printCounts(const Counts& counts, const RunInfo& info, const SweepSpec& spec) {
  std::printf("sweep: %s, %ld feasible; checks 1-%d passed %s, failed %s, not reached (early stop) %s; "
              "%.3f s, %.0f sims/s, %.3g control steps/s, backend %s (%s), %s\n",
              runCount(counts.combinations, spec.repeats).c_str(), counts.feasible, counts.checks,
              perCheck(counts, counts.passed).c_str(), perCheck(counts, counts.failed).c_str(),
              perCheck(counts, counts.not_reached).c_str(), info.wall_time_s,
              std::max(info.computed_combinations, 0L) / std::max(info.wall_time_s, 1e-9),
              std::max(info.computed_steps, 0LL) / std::max(info.wall_time_s, 1e-9), info.backend.c_str(),
              info.device.c_str(),
              precisionName(spec.precision));
  std::fflush(stdout);
}

// Reads the chunks into the outputs, writes summary.json, plots; the
// progress folder goes once everything is written.
int finish(const Options& opt, const SweepSpec& spec, const ChunkStore& store, RunInfo info,
           const ChunkWork& work, const nlohmann::json& ranks, int argc, char** argv) {
  Counts counts;
  std::vector<SimResult> all;
  Outputs out;
  double merge_s = 0;
  try {
    out = openOutputs(opt, spec);
    std::vector<ResultsWriter*> writers;
    for (auto& w : out.writers) writers.push_back(w.get());
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<double> writer_s;
    DelayMonotony monotony(spec);
    FeasibleShare share(spec);
    const ChunkConsumer consume = [&](long first, const std::vector<SimResult>& results) {
      monotony.add(first, results);
      share.add(first, results);
      if (opt.rviz) all.insert(all.end(), results.begin(), results.end());
    };
    std::map<std::string, long> chunks_by;
    counts = mergeChunks(spec, store, writers, consume, &writer_s, &chunks_by);
    merge_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (work.kernel_s > 0) info.kernel_time_s = work.kernel_s;
    nlohmann::json facts = runFacts(opt, store, work, out, writer_s, merge_s);
    facts["chunks"]["computed_by"] = chunks_by;  // per backend (and device): chunks
    if (!ranks.is_null()) facts["mpi"] = {{"ranks", ranks.size()}, {"per_rank", ranks}};
    if (monotony.applies()) {
      // Gain pairs whose feasibility comes back at a longer delay after failing.
      facts["delay_monotony"] = {{"gain_pairs", monotony.pairs()},
                                 {"not_monotone", monotony.nonMonotonePairs()},
                                 {"gains", {spec.paramNameOf(monotony.gains()[0]), spec.paramNameOf(monotony.gains()[1])}}};
    }
    if (share.applies()) {
      facts["feasible_share"] = share.summary();
      share.writeCsv(opt.out + "/feasible_share.csv", spec);
    }
    writeSummaryJson(opt.out + "/summary.json", spec, info, counts, facts);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s (the finished chunks stay in %s/progress)\n", e.what(), opt.out.c_str());
    return 5;
  }
  store.removeProgress();
  printCounts(counts, info, spec);
  if (opt.plots) {
    const int rc = runProgram(besideThisProgram("plot_sweep"), {opt.out});
    for (const std::string& f : out.temporary) std::remove((opt.out + "/" + f).c_str());
    if (rc != 0) {
      std::fprintf(stderr, "sweep: plotting failed (the results and summary.json are written)\n");
      return 6;
    }
  }
  if (opt.rviz) return publishFeasibleMarkers(argc, argv, spec, all);
  return 0;
}

// The output folder's chunk store: rank 0 prepares the folder (refusing
// another sweep's, cleaning old outputs) before the other ranks open it.
// Each rank's chunks record what computed them.
std::unique_ptr<ChunkStore> openStore(const Options& opt, const Start& start, const MpiRanks* mpi) {
  std::unique_ptr<ChunkStore> store;
  int status = 0;
  const ChunkPlan plan{start.spec.size(), start.chunk_size};
  if (!mpi || mpi->rank() == 0) {
    try {
      store.reset(new ChunkStore(opt.out, start.spec, plan, opt.overwrite, start.run_computed_by));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep: %s\n", e.what());
      status = 2;
    }
  }
  if (mpi && mpi->broadcast(status) == 0 && mpi->rank() != 0) {
    // rank 0's folder, of the same definition and backends: resumes it
    store.reset(new ChunkStore(opt.out, start.spec, plan, false, start.run_computed_by));
  }
  if (store) store->setChunkComputedBy(start.computed_by);
  return store;
}

nlohmann::json rankFacts(const RunInfo& info, const ChunkWork& work, const MpiRanks& mpi) {
  return {{"rank", mpi.rank()}, {"host", mpi.host()}, {"backend", info.backend}, {"device", info.device},
          {"chunks_computed", work.computed_chunks}, {"combinations", work.computed_combinations},
          {"chunks_resumed", work.resumed_chunks}, {"steps", work.computed_steps},
          {"compute_s", work.compute_s},
          {"simulations_per_s", work.compute_s > 0 ? work.computed_combinations / work.compute_s : 0.0}};
}

// The whole run's work from every rank's facts (rank 0's kernel figures kept).
ChunkWork overRanks(const nlohmann::json& ranks, ChunkWork work) {
  work.computed_chunks = work.resumed_chunks = work.computed_combinations = 0;
  work.computed_steps = 0;
  for (const auto& r : ranks) {
    work.computed_chunks += r["chunks_computed"].get<long>();
    work.resumed_chunks += r["chunks_resumed"].get<long>();
    work.computed_combinations += r["combinations"].get<long>();
    work.computed_steps += r["steps"].get<long long>();
    work.compute_s = std::max(work.compute_s, r["compute_s"].get<double>());
  }
  return work;
}

// Ctrl-C (SIGINT) or a kill (SIGTERM): say which chunks stay and the
// command that resumes, then end as the signal would (its status). The
// text is made before the run: a handler may only write(2).
char g_interrupt_text[4096];
size_t g_interrupt_length = 0;

void onInterrupt(int sig) {
  ssize_t ignored = write(STDERR_FILENO, g_interrupt_text, g_interrupt_length);
  (void)ignored;
  signal(sig, SIG_DFL);
  raise(sig);
}

void sayWhatStaysOnInterrupt(const Options& opt, int argc, char** argv) {
  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  const std::string text = "\nsweep: interrupted: every finished chunk stays in " + opt.out +
                           "/progress; the same command computes only the missing ones:\n  " + command + "\n";
  g_interrupt_length = std::min(text.size(), sizeof g_interrupt_text);
  std::memcpy(g_interrupt_text, text.data(), g_interrupt_length);
  signal(SIGINT, onInterrupt);
  signal(SIGTERM, onInterrupt);
}

// "1,344 combinations", or with repeats "21,504 runs (1,344 combinations x
// 16 repeats)", as the docs count them.
std::string runsText(const SweepSpec& spec) {
  const std::string runs = runCount(spec.size(), spec.repeats);
  if (spec.repeats <= 1) return runs;
  return runs + " (" + counted(spec.size() / spec.repeats, "combination", "combinations") + " x " +
         std::to_string(spec.repeats) + " repeats)";
}

int runSweep(int argc, char** argv, const Options& opt, MpiRanks* mpi) {
  const bool lead = !mpi || mpi->rank() == 0;
  // Everything that can refuse the run is checked before anything is
  // written, and under MPI all ranks agree (sweep_start.h).
  if (opt.rviz && !rvizMasterReachable(argc, argv)) return 7;
  Start start;
  if (const int rc = agreeToStart(mpi, loadAndChooseBackend(opt, mpi, start))) return rc;
  if (const int rc = agreeOnBackend(opt, mpi, start)) return rc;
  if (const int rc = agreeToStart(mpi, prepareOutput(opt, lead, start))) return rc;
  const SweepSpec& spec = start.spec;
  RunInfo info = start.info;
  const std::unique_ptr<ChunkStore> store = openStore(opt, start, mpi);
  if (!store) return 2;
  const ChunkPlan& plan = store->plan();
  Progress progress{store->doneCombinations()};
  if (lead) {
    std::fprintf(stderr, "sweep: %s: %s in %s, backend %s, %s precision%s%s%s\n", spec.name.c_str(),
                 runsText(spec).c_str(),
                 counted(plan.count(), "chunk", "chunks").c_str(), info.backend.c_str(),
                 precisionName(spec.precision), spec.early_stop ? ", early stop" : "",
                 mpi ? (", " + std::to_string(mpi->size()) + " MPI ranks").c_str() : "",
                 store->resumed() ? (", resuming: " + counted(store->doneCount(), "chunk", "chunks") + " (" +
                                     counted(progress.load(), "combination", "combinations") +
                                     ") already done").c_str()
                                  : "");
  }
  ChunkWork work;
  int status = 0;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    // MPI: no per-rank progress lines (each rank sees only its own chunks).
    ProgressMonitor monitor(progress, spec.size(), opt.quiet || mpi);
    std::unique_ptr<ChunkSource> chunks =
        mpi ? mpi->chunks(plan.count()) : std::unique_ptr<ChunkSource>(new SequentialChunks(plan.count()));
    work = runChunks(spec, *store, *chunks, BackendChoice{info.backend, opt.threads, opt.block_size}, progress);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: the %s backend failed: %s\n", info.backend.c_str(), e.what());
    status = 4;
  }
  if (mpi) status = mpi->maxOverRanks(status);  // also waits for every rank's chunks
  if (status != 0) return status;
  info.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const nlohmann::json ranks = mpi ? mpi->gather(rankFacts(info, work, *mpi)) : nlohmann::json();
  if (mpi && lead) work = overRanks(ranks, work);
  info.computed_combinations = work.computed_combinations;
  info.computed_steps = work.computed_steps;
  if (work.block_size > 0) {
    info.threads = work.block_size;
    info.note += (info.note.empty() ? "" : "; ") + std::string("grid ") + std::to_string(work.grid_size) +
                 " x block " + std::to_string(work.block_size);
  }
  const int rc = lead ? finish(opt, spec, *store, info, work, ranks, argc, argv) : 0;
  return mpi ? mpi->broadcast(rc) : rc;
}

}  // namespace

int main(int argc, char** argv) {
  std::unique_ptr<MpiRanks> mpi;
  if (MpiRanks::launchedByMpi()) {
    try {
      mpi.reset(new MpiRanks(&argc, &argv));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep: %s\n", e.what());
      return 2;
    }
  }
  const Options opt = parseOptions(argc, argv);
  sayWhatStaysOnInterrupt(opt, argc, argv);
  if (mpi && opt.rviz) {
    std::fprintf(stderr, "sweep: --rviz is for a single process: run without mpirun\n");
    return 2;
  }
  return runSweep(argc, argv, opt, mpi.get());
}
