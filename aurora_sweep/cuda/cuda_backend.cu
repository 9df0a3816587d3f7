// The `cuda` backend: one simulation per GPU thread. The kernel body is
// sweepThread() of kernel_entry.h (simulateCombination() of simulation.h,
// the very templates the CPU runs). Device memory and events are owned by
// RAII handles, every runtime call is checked, and an error that leaves the
// context unusable (a sticky error) is named as fatal.
#include <cuda_runtime.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/cuda_backend.h"
#include "aurora_sweep/kernel_entry.h"

namespace aurora_sweep {

namespace {

// Errors after which the context cannot be used again in this process.
bool isSticky(cudaError_t err) {
  switch (err) {
    case cudaErrorIllegalAddress:
    case cudaErrorLaunchFailure:
    case cudaErrorHardwareStackError:
    case cudaErrorIllegalInstruction:
    case cudaErrorMisalignedAddress:
    case cudaErrorInvalidAddressSpace:
    case cudaErrorInvalidPc:
    case cudaErrorAssert:
    case cudaErrorECCUncorrectable:
    case cudaErrorLaunchTimeout:
      return true;
    default:
      return false;
  }
}

// The architectures this build has native code for ("75,80": CMake's
// AURORA_CUDA_ARCHITECTURES less the -virtual ones). For another device the
// driver compiles the kernels' PTX when it first loads them.
#ifndef AURORA_CUDA_NATIVE_ARCHITECTURES
#define AURORA_CUDA_NATIVE_ARCHITECTURES ""
#endif

// Whether CMake compiled the kernels only to check them (aurora_sweep's
// CMakeLists.txt: no GPU and no architectures given at configure time).
#ifdef AURORA_CUDA_CHECK_BUILD
constexpr bool kCheckBuild = true;
#else
constexpr bool kCheckBuild = false;
#endif

bool hasNativeCode(const cudaDeviceProp& prop) {
  const std::string archs = std::string(",") + AURORA_CUDA_NATIVE_ARCHITECTURES + ",";
  return archs.find("," + std::to_string(10 * prop.major + prop.minor) + ",") != std::string::npos;
}

std::string errorText(cudaError_t err) {
  return std::string(cudaGetErrorName(err)) + " (" + cudaGetErrorString(err) + ")";
}

void check(cudaError_t err, const char* what) {
  if (err == cudaSuccess) return;
  std::string msg = std::string(what) + ": " + errorText(err);
  if (isSticky(err)) {
    msg += "; FATAL: a sticky error, the CUDA context of this process is unusable: run the same "
           "command again (it resumes from the chunks already written)";
  }
  throw std::runtime_error(msg);
}

// Device memory for n values of V, freed on every path out.
template <typename V>
class DeviceArray {
 public:
  explicit DeviceArray(size_t n) : n_(n) {
    if (n_ > 0) check(cudaMalloc(&data_, n_ * sizeof(V)), "cudaMalloc");
  }
  ~DeviceArray() {
    if (data_) cudaFree(data_);
  }
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  V* get() const { return data_; }
  void upload(const V* host) {
    if (n_ > 0) check(cudaMemcpy(data_, host, n_ * sizeof(V), cudaMemcpyHostToDevice), "cudaMemcpy(to device)");
  }
  void download(V* host) const {
    if (n_ > 0) check(cudaMemcpy(host, data_, n_ * sizeof(V), cudaMemcpyDeviceToHost), "cudaMemcpy(to host)");
  }

 private:
  V* data_ = nullptr;
  size_t n_;
};

class CudaEvent {
 public:
  CudaEvent() { check(cudaEventCreate(&event_), "cudaEventCreate"); }
  ~CudaEvent() { cudaEventDestroy(event_); }
  CudaEvent(const CudaEvent&) = delete;
  CudaEvent& operator=(const CudaEvent&) = delete;
  cudaEvent_t get() const { return event_; }

 private:
  cudaEvent_t event_ = nullptr;
};

// A single-robot sweep's kernel, law `Law` on its vehicle (with the state
// predictor when `Predicted`: docs/predictor.md). Its arguments stay within
// the 4 KB kernel arguments older CUDA versions (before 12.1) allow.
template <class Law, typename T, int Capacity, bool Linked, bool Predicted = false>
__global__ void sweepKernel(SimSetup<typename Law::Vehicle, T> setup, GridView grid, long first, long n,
                            SimResult* out) {
  static_assert(sizeof(setup) + sizeof(grid) + 3 * sizeof(long) <= 4096, "a kernel's arguments within 4 KB");
  sweepThread<Law, T, Capacity, Linked, Predicted>(setup, grid, first, n, out, blockIdx.x, blockDim.x, threadIdx.x);
}

// A formation sweep's kernel, of any shape (the two-drone line, the UAV-UGV
// line, the triangle): one formation per thread; its setup (the formation
// file's run, a few kB) is read from device memory; with its robots'
// predictors when `Predicted` (the AR.Drones' formations).
template <class Law, template <typename> class Shape, typename T, int Capacity, bool Linked, bool Predicted>
__global__ void formationKernel(const FormationSetup<T, Shape, typename Law::Data>* setup, GridView grid, long first,
                                long n, SimResult* out) {
  formationThread<Law, T, Capacity, Linked, Predicted>(*setup, grid, first, n, out, blockIdx.x, blockDim.x,
                                                       threadIdx.x);
}

// Calls f(T(), capacity, linked) with the kernel's compile-time parameters
// for `spec`: its precision, history tier (the tiers of
// withHistoryCapacity up to kMediumHistory; longer histories are refused)
// and whether its runs go over a link model (a kernel of its own, so the
// ideal sweeps' kernel keeps its registers and local memory).
template <class F>
void withKernelShape(const SweepSpec& spec, F&& f) {
  auto linked = [&](auto type, auto capacity) {
    if (spec.linkIdeal()) {
      f(type, capacity, std::false_type());
    } else {
      f(type, capacity, std::true_type());
    }
  };
  auto tier = [&](auto type) {
    if (spec.historyNeeded() < aurora_control::kShortHistory) {
      linked(type, std::integral_constant<int, aurora_control::kShortHistory>());
    } else {
      linked(type, std::integral_constant<int, aurora_control::kMediumHistory>());
    }
  };
  if (spec.precision == Precision::kDouble) {
    tier(double());
  } else {
    tier(float());
  }
}

// Which kernel runs a sweep of law Law (`kernel`) and how it is started:
// the constructor prepares its setup before the launch is timed (a single
// robot's by value; a formation's, about 2 kB, uploaded to device memory,
// held until the object goes after the launch's synchronisation), `launch`
// starts it.
template <class Law, typename T, int Capacity, bool Linked, bool Predicted = false>
struct SweepStart {
  static auto kernel() { return sweepKernel<Law, T, Capacity, Linked, Predicted>; }
  explicit SweepStart(const SweepSpec& spec) : setup_(makeSetup<typename Law::Vehicle, T>(spec)) {}
  void launch(unsigned blocks, int block, const GridView& grid, long first, long n, SimResult* out) const {
    sweepKernel<Law, T, Capacity, Linked, Predicted><<<blocks, block>>>(setup_, grid, first, n, out);
  }

 private:
  SimSetup<typename Law::Vehicle, T> setup_;
};
template <class Law, template <typename> class Shape, typename T, int Capacity, bool Linked, bool Predicted>
struct FormationStart {
  using Setup = FormationSetup<T, Shape, typename Law::Data>;
  static auto kernel() { return formationKernel<Law, Shape, T, Capacity, Linked, Predicted>; }
  explicit FormationStart(const SweepSpec& spec) : setup_(1) {
    spec.withFormation([&](const auto& run, auto) { upload(spec, run); });
  }
  void launch(unsigned blocks, int block, const GridView& grid, long first, long n, SimResult* out) const {
    formationKernel<Law, Shape, T, Capacity, Linked, Predicted><<<blocks, block>>>(setup_.get(), grid, first, n, out);
  }

 private:
  // The spec's run of this shape (withFormation's run of another shape is
  // never this kernel's: withKernel chose it by the same call).
  void upload(const SweepSpec& spec, const ShapeRun<double, Shape, typename Law::Data>& run) {
    const Setup host = makeFormationSetup<T>(spec, run);
    setup_.upload(&host);
  }
  template <class OtherRun>
  void upload(const SweepSpec&, const OtherRun&) {}

  DeviceArray<Setup> setup_;
};

// The template of a formation run's shape (ShapeRun<T, Shape, Data>'s Shape).
template <class Run>
struct ShapeTemplateOf;
template <typename T, template <typename> class Shape, class Data>
struct ShapeTemplateOf<aurora_control::FormationRun<T, Shape<T>, Data>> {
  template <class Law, typename U, int Capacity, bool Linked, bool Predicted>
  using Start = FormationStart<Law, Shape, U, Capacity, Linked, Predicted>;
};

// Whether this backend has predicting kernels (sweep.predictor) for law
// Law: its family's data declares kGpuPredictor (each family's kernels cost
// build time); the others' predicting sweeps run on the cpu backends.
template <class Data>
constexpr bool gpuPredicts(decltype(Data::kGpuPredictor)*) {
  return Data::kGpuPredictor;
}
template <class Data>
constexpr bool gpuPredicts(...) {
  return false;
}
template <class Law>
using GpuPredicts = std::integral_constant<bool, gpuPredicts<typename Law::Data>(nullptr)>;

// f(Law()) where Law has predicting kernels (cudaDelayProblem refused the
// others before a kernel is chosen).
template <class Law, class F>
void withPredictingLaw(std::true_type, Law law, F& f) {
  f(law);
}
template <class Law, class F>
void withPredictingLaw(std::false_type, Law, F&) {}

// The laws with predicting kernels, comma separated.
std::string gpuPredictingLaws() {
  std::string names;
  aurora_control::forEachLaw([&](auto law) {
    if (GpuPredicts<decltype(law)>::value) names += (names.empty() ? "" : ", ") + std::string(law.name());
  });
  return names;
}

// A kernel's start as a type, without preparing it.
template <class Start>
struct StartOf {
  using type = Start;
};

// Calls f(StartOf<Start>()) with the start of the kernel that runs `spec`.
template <class F>
void withKernel(const SweepSpec& spec, F&& f) {
  withKernelShape(spec, [&](auto type, auto capacity, auto linked) {
    using T = decltype(type);
    constexpr int kCapacity = decltype(capacity)::value;
    constexpr bool kLinked = decltype(linked)::value;
    if (spec.formation()) {
      spec.withFormation([&](const auto& run, auto law) {
        using Shape = ShapeTemplateOf<typename std::decay<decltype(run)>::type>;
        withFormationPredictor(run, [&](auto predicted) {
          f(StartOf<typename Shape::template Start<decltype(law), T, kCapacity, kLinked, decltype(predicted)::value>>());
        });
      });
    } else if (spec.predicting()) {
      const auto start = [&](auto law) { f(StartOf<SweepStart<decltype(law), T, kCapacity, kLinked, true>>()); };
      withSweepLaw(spec, [&](auto law) { withPredictingLaw(GpuPredicts<decltype(law)>(), law, start); });
    } else {
      withSweepLaw(spec, [&](auto law) { f(StartOf<SweepStart<decltype(law), T, kCapacity, kLinked>>()); });
    }
  });
}

// The kernel's attributes for `spec` (loading its module: fails with the
// reason where this build has no code for the device or the driver is old).
cudaFuncAttributes kernelAttributes(const SweepSpec& spec) {
  cudaFuncAttributes attr{};
  withKernel(spec, [&](auto of) {
    check(cudaFuncGetAttributes(&attr, decltype(of)::type::kernel()), "loading the sweep kernel (cudaFuncGetAttributes)");
  });
  return attr;
}

int defaultBlockSize(const SweepSpec& spec) {
  int min_grid = 0, block = 0;
  withKernel(spec, [&](auto of) {
    check(cudaOccupancyMaxPotentialBlockSize(&min_grid, &block, decltype(of)::type::kernel()),
          "cudaOccupancyMaxPotentialBlockSize");
  });
  return block;
}

// An attribute of the current device.
int deviceAttribute(cudaDeviceAttr which) {
  int device = 0, value = 0;
  check(cudaGetDevice(&device), "cudaGetDevice");
  check(cudaDeviceGetAttribute(&value, which, device), "cudaDeviceGetAttribute");
  return value;
}

// Only the rows of the chunk [first, first + n) of a points design go to
// the device (a whole 10^8-row design would be gigabytes per chunk); with
// repeats, index i is row i / repeats.
struct DeviceGrid {
  GridView view{};
  std::vector<std::unique_ptr<DeviceArray<double>>> buffers;
  const double* upload(const double* host, size_t n) {
    buffers.emplace_back(new DeviceArray<double>(n));
    buffers.back()->upload(host);
    return buffers.back()->get();
  }
  DeviceGrid(const GridView& host, long first, long n) : view(host) {
    for (int a = 0; a < host.n_axes; ++a) view.values[a] = upload(host.values[a], static_cast<size_t>(host.count[a]));
    if (host.n_points > 0) {
      const size_t cols = static_cast<size_t>(host.point_cols);
      const long row = first / host.repeats, rows = (first + n - 1) / host.repeats - row + 1;
      view.points = upload(host.points + static_cast<size_t>(row) * cols, static_cast<size_t>(rows) * cols);
      view.points_first = row;
    }
  }
};

// Runs `spec`'s range with kernel start Start and times it.
template <class Start>
CudaRun launch(const SweepSpec& spec, int block_size, std::vector<SimResult>& out) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const long first = spec.rangeBegin(), n = spec.rangeSize();
  const DeviceGrid grid(spec.view(), first, n);
  CudaRun run;
  run.block_size = block_size > 0 ? block_size : defaultBlockSize(spec);
  run.grid_size = blocksFor(n, run.block_size);
  DeviceArray<SimResult> dev_out(static_cast<size_t>(n));
  const Start starter(spec);
  CudaEvent start, stop;
  cudaGetLastError();  // a stale error of an earlier, failed call is not this launch's
  check(cudaEventRecord(start.get()), "cudaEventRecord");
  starter.launch(static_cast<unsigned>(run.grid_size), run.block_size, grid.view, first, n, dev_out.get());
  check(cudaGetLastError(), "kernel launch");
  check(cudaEventRecord(stop.get()), "cudaEventRecord");
  check(cudaEventSynchronize(stop.get()), "kernel");
  float ms = 0;
  check(cudaEventElapsedTime(&ms, start.get(), stop.get()), "cudaEventElapsedTime");
  run.kernel_s = ms / 1e3;
  out.resize(static_cast<size_t>(n));
  dev_out.download(out.data());
  run.total_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return run;
}

}  // namespace

bool cudaCompiledIn() { return true; }

DeviceChoice selectCudaDevice(int local_rank, int local_size) {
  DeviceChoice c;
  if (cudaGetDeviceCount(&c.devices) != cudaSuccess || c.devices == 0) {
    cudaGetLastError();  // clear: probeCudaDevice reports the error
    c.devices = 0;
    return c;
  }
  c.device = local_rank % c.devices;
  const cudaError_t err = cudaSetDevice(c.device);
  if (err != cudaSuccess) {
    c.ok = false;
    c.note = "cudaSetDevice(" + std::to_string(c.device) + "): " + errorText(err);
    return c;
  }
  if (local_size > c.devices) {
    c.note = std::to_string(local_size) + " ranks on this host share " + std::to_string(c.devices) +
             " GPU(s): local rank " + std::to_string(local_rank) + " uses device " + std::to_string(c.device) +
             " with " + std::to_string((local_size - 1 - c.device) / c.devices) + " other rank(s)";
  }
  return c;
}

CudaDevice probeCudaDevice() {
  CudaDevice d;
  int count = 0;
  const cudaError_t err = cudaGetDeviceCount(&count);
  if (err != cudaSuccess) {
    cudaGetLastError();
    d.error = "cudaGetDeviceCount: " + errorText(err);
    return d;
  }
  if (count == 0) {
    d.error = "the CUDA runtime reports no device";
    return d;
  }
  int device = 0;  // the current one (selectCudaDevice under MPI)
  cudaDeviceProp prop;
  const cudaError_t perr = cudaGetDevice(&device) == cudaSuccess ? cudaGetDeviceProperties(&prop, device)
                                                                  : cudaErrorInvalidDevice;
  if (perr != cudaSuccess) {
    d.error = "cudaGetDeviceProperties: " + errorText(perr);
    return d;
  }
  // Loading a kernel shows that the driver runs this build's code on this
  // device (an old driver, or no SASS/PTX for its architecture, fails here
  // and not at the first chunk).
  if (!hasNativeCode(prop)) {
    std::fprintf(stderr, "cuda: this build has no native code for '%s' (compute capability %d.%d): the driver "
                 "compiles the kernels' PTX before the first chunk (a minute or two when not in its cache, "
                 "~/.nv/ComputeCache); build with -DAURORA_CUDA_ARCHITECTURES=%d%d to have it in the build\n",
                 prop.name, prop.major, prop.minor, prop.major, prop.minor);
    if (kCheckBuild) {
      std::fprintf(stderr, "cuda: this build compiled the kernels only to check them (AURORA_CUDA_CHECK_ONLY, "
                   "the default where CMake found no GPU and was given no architectures: PTX at NVVM -O0), not "
                   "for speed: build with -DAURORA_CUDA_ARCHITECTURES=%d%d for an optimized kernel\n",
                   prop.major, prop.minor);
    }
  }
  SweepSpec probe;
  try {
    kernelAttributes(probe);
  } catch (const std::exception& e) {
    cudaGetLastError();
    d.error = std::string("'") + prop.name + "' (compute capability " + std::to_string(prop.major) + "." +
              std::to_string(prop.minor) + "): " + e.what();
    return d;
  }
  d.usable = true;
  d.name = prop.name;
  d.device = device;
  return d;
}

long cudaMaxDelay() { return aurora_control::kMediumHistory - 1; }

std::string cudaDelayProblem(const SweepSpec& spec) {
  bool predicts = false;  // withSweepLaw's choice has predicting kernels
  aurora_control::withLawNamed(spec.controller, [&](auto law) { predicts = GpuPredicts<decltype(law)>::value; });
  if (spec.predicting() && !predicts) {
    return "the state predictor (sweep.predictor) has CUDA kernels for the laws " + gpuPredictingLaws() +
           " only, not " + spec.controller + ": use --backend cpu";
  }
  if (spec.historyNeeded() <= cudaMaxDelay()) return "";
  return "the cuda backend holds delays (with a link's jitter) up to " + std::to_string(cudaMaxDelay()) +
         " samples (each GPU thread keeps its history in local memory); this sweep reaches " +
         std::to_string(spec.historyNeeded()) + ": use --backend cpu";
}

std::string cudaLaunchProblem(const SweepSpec& spec, int block_size) {
  const std::string delay = cudaDelayProblem(spec);
  if (!delay.empty()) return delay;
  try {
    const cudaFuncAttributes attr = kernelAttributes(spec);
    if (block_size > attr.maxThreadsPerBlock) {
      return "--block-size " + std::to_string(block_size) + " is above what this kernel (" +
             std::to_string(attr.numRegs) + " registers per thread) can launch: accepted up to " +
             std::to_string(attr.maxThreadsPerBlock) + " threads per block";
    }
    // The driver reserves the kernel's local memory (the delay history) for
    // as many threads as the device can hold (not this kernel's occupancy),
    // for the whole process, at the first launch.
    const long resident = static_cast<long>(deviceAttribute(cudaDevAttrMultiProcessorCount)) *
                          deviceAttribute(cudaDevAttrMaxThreadsPerMultiProcessor);
    const double reserve = double(attr.localSizeBytes) * double(resident);
    size_t free_bytes = 0, total = 0;
    check(cudaMemGetInfo(&free_bytes, &total), "cudaMemGetInfo");
    if (reserve > 0.9 * double(free_bytes)) {
      return "the kernel's local memory (" + std::to_string(attr.localSizeBytes) + " B per thread x " +
             std::to_string(resident) + " threads the device can hold = " + std::to_string(long(reserve / 1e6)) +
             " MB) does not fit in the " + std::to_string(long(free_bytes / 1e6)) +
             " MB free on the device: fewer ranks per GPU, shorter delays (a smaller history tier), "
             "float, or --backend cpu";
    }
  } catch (const std::exception& e) {
    cudaGetLastError();
    return e.what();
  }
  return "";
}

long cudaResidentThreads(const SweepSpec& spec, int block_size) {
  int blocks = 0;
  const int block = block_size > 0 ? block_size : defaultBlockSize(spec);
  withKernel(spec, [&](auto of) {
    check(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&blocks, decltype(of)::type::kernel(), block, 0),
          "cudaOccupancyMaxActiveBlocksPerMultiprocessor");
  });
  return static_cast<long>(deviceAttribute(cudaDevAttrMultiProcessorCount)) * blocks * block;
}

CudaRun runCuda(const SweepSpec& spec, int block_size, std::vector<SimResult>& out) {
  const std::string delay = cudaDelayProblem(spec);
  if (!delay.empty()) throw std::runtime_error(delay);
  CudaRun run;
  withKernel(spec, [&](auto of) { run = launch<typename decltype(of)::type>(spec, block_size, out); });
  return run;
}

}  // namespace aurora_sweep
