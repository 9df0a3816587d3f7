#include "sweep_start.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include "aurora_common/ros/config_dir.h"
#include "aurora_control/params/shipped_files.h"
#include "aurora_sweep/backends.h"
#include "aurora_sweep/cuda_backend.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_plan.h"

namespace aurora_sweep {

namespace {

// Creates `dir` (and its parents) and checks that it is writable; records
// the folders it created, deepest last (a later refusal removes them).
StartCheck makeWritableDir(const std::string& dir, std::vector<std::string>& created) {
  std::string partial;
  for (size_t i = 0; i <= dir.size(); ++i) {
    if (i == dir.size() || dir[i] == '/') {
      if (!partial.empty() && mkdir(partial.c_str(), 0755) == 0) created.push_back(partial);
    }
    if (i < dir.size()) partial += dir[i];
  }
  const std::string probe = dir + "/.sweep_write_test." + std::to_string(getpid());
  FILE* f = std::fopen(probe.c_str(), "w");
  if (!f) {
    return {2, "output folder '" + dir + "' is not writable (" + std::strerror(errno) +
                   "): choose another with --out"};
  }
  std::fclose(f);
  std::remove(probe.c_str());
  return {};
}

// The cuda backend's checks before anything is written: the device (with a
// kernel loaded), the sweep's delays, the block size against the kernel's
// registers, the local memory of the resident threads.
StartCheck checkCuda(const Options& opt, const SweepSpec& spec, RunInfo& info) {
  const std::string delay = cudaDelayProblem(spec);
  CudaDevice dev = probeCudaDevice();
  if (opt.backend == "auto") {
    const std::string why = !dev.usable ? dev.error : !delay.empty() ? delay
                                                    : cudaLaunchProblem(spec, opt.block_size);
    if (why.empty()) {
      info.backend = "cuda", info.device = dev.name;
      info.note = "auto: CUDA device '" + dev.name + "' works";
    } else {
      info.backend = "cpu";
      info.note = "auto: not the cuda backend (" + why + "), using the cpu backend";
    }
    std::fprintf(stderr, "sweep: %s\n", info.note.c_str());
    return {};
  }
  if (!delay.empty()) return {2, "--backend cuda: " + delay};  // no device needed to know
  if (!dev.usable) return {3, "--backend cuda: no usable CUDA device: " + dev.error};
  const std::string launch = cudaLaunchProblem(spec, opt.block_size);
  if (!launch.empty()) return {2, "--backend cuda on '" + dev.name + "': " + launch};
  info.backend = "cuda", info.device = dev.name;
  return {};
}

// Picks the backend (auto: cuda when a device works, else cpu) and checks
// that it can run.
StartCheck chooseBackend(const Options& opt, const SweepSpec& spec, RunInfo& info) {
  info.backend = opt.backend;
  if (opt.backend == "cuda" || opt.backend == "auto") {
    const StartCheck cuda = checkCuda(opt, spec, info);
    if (cuda.status) return cuda;
  }
  info.threads = info.backend == "scalar" ? 1 : opt.threads;
  try {
    if (info.backend == "scalar") info.device = "scalar loop";
    if (info.backend == "cpu") {  // an AURORA_SWEEP_SIMD this CPU cannot run is refused here
      info.device = cpuBatchArch(spec.precision);
      info.lanes = cpuBatchLanes(spec.precision);
    }

  } catch (const std::exception& e) {
    return {2, e.what()};
  }
  if ((opt.output == "hdf5" || opt.output == "both") && !hdf5Available()) {
    return {2, "--output " + opt.output + ": this build has no HDF5 (install libhdf5-dev and rebuild)"};
  }
  return {};
}

// What computed the chunks: a resume must use the same (the backends agree
// to rounding only, so mixed chunks would equal no uninterrupted run).
std::string computedBy(const RunInfo& info) {
  return info.backend == "scalar" ? "scalar" : info.backend + " (" + info.device + ")";
}

// Default chunk size: about 64 chunks (ranks and threads balance, a crash
// loses little), but not so small that file writes count, nor so large that
// the memory of one chunk grows without bound. On a GPU a chunk is one
// launch: at least four times the threads the device keeps resident, or it
// starves (4,096 threads are a tenth of an H100).
long chunkSizeFor(const Options& opt, const SweepSpec& spec, const RunInfo& info) {
  if (opt.chunk_size > 0) return opt.chunk_size;
  const long combinations = spec.size();
  long size = std::min(262144L, std::max(4096L, combinations / 64));
  if (info.backend == "cuda") size = std::max(size, 4 * cudaResidentThreads(spec, opt.block_size));
  return std::max(1L, std::min(size, combinations));
}

// Says up front what the sweep costs (time at a measured rate, bytes) and
// refuses one that cannot fit on the disk.
StartCheck checkPlan(const Options& opt, const Start& s, bool lead) {
  SweepPlan plan;
  try {
    plan = planSweep(s.spec, BackendChoice{s.info.backend, opt.threads, opt.block_size}, opt.out,
                     outputFormat(opt, s.spec.size()), s.chunk_size);
  } catch (const std::exception& e) {
    return {4, "the " + s.info.backend + " backend failed: " + e.what()};
  }
  if (lead && !opt.quiet) std::fprintf(stderr, "sweep: plan: %s\n", planText(plan).c_str());
  if (plan.fits() || opt.ignore_free_space) return {};
  // The estimate counts every row in either format (--rows feasible's count is known only after the run).
  return {2, "refused: " + plan.volume + " cannot hold this sweep (" + planText(plan) +
                 "): choose an --out on a volume with more room, sweep fewer combinations, or give "
                 "--ignore-free-space (--rows feasible may write fewer rows, as many as turn out feasible)"};
}

// One sweep at a time in a folder: an exclusive flock on --out/.sweep.lock,
// held until this process ends (the kernel releases it on any exit, a
// crash and Ctrl-C included). The holder writes its pid and host there, so
// a second sweep is refused at once naming them (two sweeps computed the
// same chunks and the second failed after removing progress/).
StartCheck lockOutput(const std::string& dir) {
  const std::string path = dir + "/.sweep.lock";
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return {2, "cannot open '" + path + "': " + std::strerror(errno)};
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char holder[256] = {};
    const ssize_t n = pread(fd, holder, sizeof holder - 1, 0);
    std::string who = n > 0 ? std::string(holder, static_cast<size_t>(n)) : std::string("another process");
    while (!who.empty() && (who.back() == '\n' || who.back() == ' ')) who.pop_back();
    close(fd);
    return {2, "output folder '" + dir + "' is in use by another sweep (" + who +
                   "): wait for it to end (the same command then resumes or reuses its chunks), or choose another --out"};
  }
  char host[128] = {};
  gethostname(host, sizeof host - 1);
  const std::string me = "pid " + std::to_string(getpid()) + " on host " + host + "\n";
  if (ftruncate(fd, 0) != 0 || pwrite(fd, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size())) {
    std::fprintf(stderr, "sweep: warning: cannot write '%s': %s\n", path.c_str(), std::strerror(errno));
  }
  return {};  // fd stays open: the lock lives as long as this process
}

// A test switch: the rank it names fails its start check, as a rank whose
// device check fails would (the MPI agreement test).
StartCheck forcedFailure(const MpiRanks* mpi) {
  const char* v = std::getenv("AURORA_SWEEP_TEST_FAIL_RANK");
  if (!mpi || !v || std::atoi(v) != mpi->rank()) return {};
  return {3, "the device check fails (forced by AURORA_SWEEP_TEST_FAIL_RANK, a test switch)"};
}

}  // namespace

std::string outputFormat(const Options& opt, long combinations) {
  if (opt.output != "auto") return opt.output;
  return combinations > 1000000 && hdf5Available() ? "hdf5" : "csv";
}

StartCheck loadAndChooseBackend(const Options& opt, const MpiRanks* mpi, Start& s) {
  try {
    const std::string config_dir = opt.config_dir.empty() ? aurora_common::configDir() : opt.config_dir;
    // A shipped NAME is config/sweeps/NAME.yaml (flight's rule, shipped_files.h).
    s.spec = loadSweepFile(aurora_control::shippedOrPath(opt.config, config_dir, "sweeps"), config_dir);
  } catch (const std::exception& e) {
    return {2, e.what()};
  }
  if (!opt.precision.empty()) s.spec.precision = opt.precision == "float" ? Precision::kFloat : Precision::kDouble;
  const StartCheck forced = forcedFailure(mpi);
  if (forced.status) return forced;
  if (mpi && (opt.backend == "cuda" || opt.backend == "auto")) {
    const DeviceChoice d = selectCudaDevice(mpi->localRank(), mpi->localSize());  // one GPU per rank on a host
    if (!d.ok) return {3, d.note};
    if (!d.note.empty()) std::fprintf(stderr, "sweep: rank %d: %s\n", mpi->rank(), d.note.c_str());
  }
  const StartCheck backend = chooseBackend(opt, s.spec, s.info);
  if (backend.status) return backend;
  s.computed_by = s.run_computed_by = computedBy(s.info);
  try {
    s.chunk_size = chunkSizeFor(opt, s.spec, s.info);
  } catch (const std::exception& e) {
    return {4, e.what()};
  }
  return {};
}

StartCheck prepareOutput(const Options& opt, bool lead, Start& s) {
  const StartCheck dir = makeWritableDir(opt.out, s.created);
  if (dir.status) return dir;
  if (lead) {
    const StartCheck lock = lockOutput(opt.out);
    if (lock.status) return lock;
  }
  const StartCheck plan = checkPlan(opt, s, lead);
  if (plan.status && lead && !s.created.empty()) {  // nothing left behind
    std::remove((opt.out + "/.sweep.lock").c_str());
    for (auto d = s.created.rbegin(); d != s.created.rend(); ++d) rmdir(d->c_str());
  }
  return plan;
}

int agreeToStart(const MpiRanks* mpi, const StartCheck& mine) {
  if (!mpi) {
    if (mine.status) std::fprintf(stderr, "sweep: %s\n", mine.message.c_str());
    return mine.status;
  }
  const nlohmann::json all = mpi->gather({{"status", mine.status}, {"message", mine.message}, {"host", mpi->host()}});
  if (mpi->rank() == 0) {
    long failed = 0;
    for (size_t r = 0; r < all.size(); ++r) {
      if (all[r]["status"].get<int>() == 0) continue;
      ++failed;
      std::fprintf(stderr, "sweep: rank %zu (%s): %s\n", r, all[r]["host"].get<std::string>().c_str(),
                   all[r]["message"].get<std::string>().c_str());
    }
    if (failed > 0) {
      std::fprintf(stderr, "sweep: %ld of %d ranks cannot start: every rank stops, nothing was written\n",
                   failed, mpi->size());
    }
  }
  return mpi->maxOverRanks(mine.status);
}

int agreeOnBackend(const Options& opt, const MpiRanks* mpi, Start& s) {
  if (!mpi) return 0;
  const nlohmann::json all = mpi->gather(s.computed_by);
  int status = 0;
  std::string run = s.computed_by;
  if (mpi->rank() == 0) {
    std::map<std::string, std::vector<size_t>> ranks_of;
    for (size_t r = 0; r < all.size(); ++r) ranks_of[all[r].get<std::string>()].push_back(r);
    if (ranks_of.size() > 1) {
      std::string list;
      for (const auto& kv : ranks_of) {
        list += (list.empty() ? "" : "; ") + kv.first + ": rank";
        for (size_t r : kv.second) list += " " + std::to_string(r);
      }
      run = "mixed: " + list;
      if (!opt.mixed_backends) {
        std::fprintf(stderr, "sweep: the ranks would compute on different backends (%s): their chunks agree "
                     "to rounding only, so the result would equal no single-backend run; give the same "
                     "--backend to every rank (not auto), or --mixed-backends to accept it\n", list.c_str());
        status = 2;
      }
    }
  }
  status = mpi->broadcast(status);
  s.run_computed_by = mpi->broadcast(run);  // rank 0's, the same on every rank
  return status;
}

}  // namespace aurora_sweep
