// sweep: runs a grid search (or a list of points) of controller gains x delay
// and tells which combinations fly safely.
//   rosrun aurora_sweep sweep --config FILE --out DIR [--backend scalar|cpu|cuda|auto]
//                             [--precision double|float] [--threads N] [--no-plots] [--rviz]
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

#include "aurora_sim/config_dir.h"
#include "aurora_sweep/backends.h"
#include "aurora_sweep/cuda_backend.h"
#include "aurora_sweep/recent_rate.h"
#include "aurora_sweep/results.h"
#include "aurora_sweep/rviz_markers.h"
#include "aurora_sweep/sweep_file.h"

namespace {

using namespace aurora_sweep;

const char* kUsage =
    "usage: sweep --config FILE --out DIR [options]\n"
    "\n"
    "Runs every combination of a sweep file (controller gains x delay) and writes\n"
    "DIR/results.csv (one row per combination), DIR/summary.json and DIR/*.png.\n"
    "\n"
    "options:\n"
    "  --config FILE        sweep file (YAML), e.g. config/sweeps/positioning_delay.yaml\n"
    "  --out DIR            output folder (created; must be writable)\n"
    "  --backend NAME       scalar (one simulation at a time, one thread), cpu (SIMD lanes\n"
    "                       on all cores), cuda (one simulation per GPU thread), or auto\n"
    "                       (cuda when a device works, else cpu). Default: auto\n"
    "  --precision P        double or float (default: the sweep file's, else double)\n"
    "  --threads N          cpu backend threads (default: all cores)\n"
    "  --block-size N       cuda threads per block (default: chosen by occupancy)\n"
    "  --config-dir DIR     where vehicle files are looked up (default: $AURORA_CONFIG_DIR, else\n"
    "                       the aurora_config package on the ROS package path)\n"
    "  --no-plots           skip the PNG plots\n"
    "  --rviz               publish the feasible set as a latched MarkerArray\n"
    "                       (/sweep/feasible, frame 'sweep') and keep running until Ctrl-C\n"
    "  --quiet              no progress on stderr\n"
    "  -h, --help           this text\n"
    "\n"
    "The cpu backend picks at run time the widest SIMD build this CPU runs;\n"
    "AURORA_SWEEP_SIMD=avx512|avx2|sse4_2|none forces one (none: no SIMD lanes).\n";

struct Options {
  std::string config, out, backend = "auto", precision, config_dir;  // empty: configDir()
  int threads = 0;
  int block_size = 0;
  bool plots = true, rviz = false, quiet = false;
};

// plot_sweep is installed beside this program (devel space: catkin's relay;
// install space: the script), so it is found without a source path.
std::string besideThisProgram(const std::string& name) {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return name;  // let the shell look it up on PATH
  std::string dir(self, static_cast<size_t>(n));
  return dir.substr(0, dir.rfind('/') + 1) + name;
}

[[noreturn]] void usageError(const std::string& msg) {
  std::fprintf(stderr, "sweep: %s\n\n%s", msg.c_str(), kUsage);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) usageError(std::string(name) + " needs a value");
      return argv[++i];
    };
    auto positive = [&](const char* name) {
      const std::string v = value(name);
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || n < 1 || n > 65536) {
        usageError(std::string(name) + " '" + v + "' is invalid: accepted a whole number in [1, 65536]");
      }
      return static_cast<int>(n);
    };
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (a == "--config") {
      o.config = value("--config");
    } else if (a == "--out") {
      o.out = value("--out");
    } else if (a == "--backend") {
      o.backend = value("--backend");
      if (o.backend != "scalar" && o.backend != "cpu" && o.backend != "cuda" && o.backend != "auto") {
        usageError("--backend '" + o.backend + "' is unknown: accepted scalar, cpu, cuda, auto");
      }
    } else if (a == "--precision") {
      o.precision = value("--precision");
      if (o.precision != "double" && o.precision != "float") {
        usageError("--precision '" + o.precision + "' is unknown: accepted double, float");
      }
    } else if (a == "--threads") {
      o.threads = positive("--threads");
    } else if (a == "--block-size") {
      o.block_size = positive("--block-size");
    } else if (a == "--config-dir") {
      o.config_dir = value("--config-dir");
    } else if (a == "--no-plots") {
      o.plots = false;
    } else if (a == "--rviz") {
      o.rviz = true;
    } else if (a == "--quiet") {
      o.quiet = true;
    } else if (a.rfind("__", 0) == 0) {
      // ROS remapping arguments (rosrun/roslaunch): handled by ros::init with --rviz.
    } else {
      usageError("unknown argument '" + a + "'");
    }
  }
  if (o.config.empty()) usageError("--config FILE is required");
  if (o.out.empty()) usageError("--out DIR is required");
  if (o.threads == 0) o.threads = std::max(1u, std::thread::hardware_concurrency());
  return o;
}

void makeWritableDir(const std::string& dir) {
  std::string partial;
  for (size_t i = 0; i <= dir.size(); ++i) {
    if (i == dir.size() || dir[i] == '/') {
      if (!partial.empty()) mkdir(partial.c_str(), 0755);
    }
    if (i < dir.size()) partial += dir[i];
  }
  const std::string probe = dir + "/.sweep_write_test";
  FILE* f = std::fopen(probe.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "sweep: output folder '%s' is not writable (%s): choose another with --out\n",
                 dir.c_str(), std::strerror(errno));
    std::exit(2);
  }
  std::fclose(f);
  std::remove(probe.c_str());
}

// Prints progress with an ETA to stderr once a second while `total` runs.
class ProgressMonitor {
 public:
  ProgressMonitor(const Progress& progress, long total, bool quiet)
      : progress_(progress), total_(total), quiet_(quiet), start_(Clock::now()) {
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

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse(argc, argv);
  SweepSpec spec;
  try {
    spec = loadSweepFile(opt.config, opt.config_dir.empty() ? aurora_sim::configDir() : opt.config_dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
  if (!opt.precision.empty()) {
    spec.precision = opt.precision == "float" ? Precision::kFloat : Precision::kDouble;
  }
  // Everything that can refuse the run is checked before the output folder
  // is created and before any simulation: the device, the ROS master.
  if (opt.rviz && !rvizMasterReachable(argc, argv)) return 7;

  RunInfo info;
  std::string backend = opt.backend;
  if (backend == "cuda" || backend == "auto") {
    CudaDevice dev = probeCudaDevice();
    if (dev.usable && spec.max_delay > cudaMaxDelay() && backend == "auto") {
      dev.usable = false;
      dev.error = "the sweep's delays reach " + std::to_string(spec.max_delay) +
                  " samples, above the cuda backend's " + std::to_string(cudaMaxDelay());
    }
    if (dev.usable) {
      backend = "cuda";
      info.device = dev.name;
      if (opt.backend == "auto") info.note = "auto: CUDA device '" + dev.name + "' works";
    } else if (backend == "cuda") {
      std::fprintf(stderr, "sweep: --backend cuda: no usable CUDA device: %s\n", dev.error.c_str());
      return 3;
    } else {
      backend = "cpu";
      info.note = "auto: no usable CUDA device (" + dev.error + "), using the cpu backend";
    }
    if (opt.backend == "auto") std::fprintf(stderr, "sweep: %s\n", info.note.c_str());
  }
  if (backend == "cpu") {
    try {
      cpuBatchArch(spec.precision);  // an AURORA_SWEEP_SIMD this CPU cannot run is refused here
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep: %s\n", e.what());
      return 2;
    }
  }
  info.backend = backend;
  makeWritableDir(opt.out);

  const long total = spec.size();
  std::fprintf(stderr, "sweep: %s: %ld combinations, backend %s, %s precision%s\n",
               spec.name.c_str(), total, backend.c_str(), precisionName(spec.precision),
               spec.early_stop ? ", early stop" : "");
  std::vector<SimResult> results;
  Progress progress{0};
  const auto t0 = std::chrono::steady_clock::now();
  try {
    ProgressMonitor monitor(progress, total, opt.quiet);
    if (backend == "scalar") {
      info.threads = 1;
      info.device = "scalar loop";
      runScalar(spec, results, progress);
    } else if (backend == "cpu") {
      info.threads = opt.threads;
      info.lanes = cpuBatchLanes(spec.precision);
      info.device = cpuBatchArch(spec.precision);
      runCpuBatch(spec, opt.threads, results, progress);
    } else {
      const CudaRun run = runCuda(spec, opt.block_size, results);
      info.kernel_time_s = run.kernel_s;
      info.threads = run.block_size;
      info.note += (info.note.empty() ? "" : "; ") + std::string("grid ") +
                   std::to_string(run.grid_size) + " x block " + std::to_string(run.block_size);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: the %s backend failed: %s\n", backend.c_str(), e.what());
    return 4;
  }
  info.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Counts counts =
      countResults(results, aurora_control::studyIterationCount(spec.duration, spec.vehicle.Ts));
  try {
    writeResultsCsv(opt.out + "/results.csv", spec, results);
    writeSummaryJson(opt.out + "/summary.json", spec, info, counts);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 5;
  }
  std::printf("sweep: %ld combinations, %ld feasible; checks 1-4 passed %ld %ld %ld %ld, failed %ld %ld %ld "
              "%ld, not reached (early stop) %ld %ld %ld %ld; "
              "%.3f s, %.0f sims/s, %.3g control steps/s, backend %s (%s), %s\n",
              counts.combinations, counts.feasible, counts.passed[0], counts.passed[1],
              counts.passed[2], counts.passed[3], counts.failed[0], counts.failed[1], counts.failed[2],
              counts.failed[3], counts.not_reached[0], counts.not_reached[1], counts.not_reached[2],
              counts.not_reached[3], info.wall_time_s,
              counts.combinations / std::max(info.wall_time_s, 1e-9),
              counts.steps / std::max(info.wall_time_s, 1e-9), backend.c_str(), info.device.c_str(),
              precisionName(spec.precision));
  std::fflush(stdout);
  if (opt.plots) {
    const std::string cmd = "\"" + besideThisProgram("plot_sweep") + "\" \"" + opt.out + "\"";
    if (std::system(cmd.c_str()) != 0) {
      std::fprintf(stderr, "sweep: plotting failed (results.csv and summary.json are written)\n");
      return 6;
    }
  }
  if (opt.rviz) return publishFeasibleMarkers(argc, argv, spec, results);
  return 0;
}
