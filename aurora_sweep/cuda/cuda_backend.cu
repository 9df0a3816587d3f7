// The `cuda` backend: one simulation per GPU thread. The kernel body is
// simulateCombination() of simulation.h, the very templates the CPU runs.
#include <cuda_runtime.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/cuda_backend.h"

namespace aurora_sweep {

namespace {

void check(cudaError_t err, const char* what) {
  if (err != cudaSuccess) {
    throw std::runtime_error(std::string(what) + ": " + cudaGetErrorName(err) + " (" +
                             cudaGetErrorString(err) + ")");
  }
}

template <aurora_control::LawType Law, typename T, int Capacity>
__global__ void sweepKernel(SimSetup<T> setup, GridView grid, long first, long n, SimResult* out) {
  const long i = static_cast<long>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= n) return;
  out[i] = simulateCombination<Law, T, Capacity>(setup, grid, first + i);  // the spec's range
}

// Device copies of the per-axis values (not a table of combinations).
struct DeviceGrid {
  GridView view{};
  std::vector<double*> buffers;
  ~DeviceGrid() {
    for (double* b : buffers) cudaFree(b);
  }
  double* upload(const double* host, size_t n) {
    double* dev = nullptr;
    check(cudaMalloc(&dev, n * sizeof(double)), "cudaMalloc(grid values)");
    buffers.push_back(dev);
    check(cudaMemcpy(dev, host, n * sizeof(double), cudaMemcpyHostToDevice), "cudaMemcpy(grid values)");
    return dev;
  }
};

template <aurora_control::LawType Law, typename T, int Capacity>
CudaRun launch(const SweepSpec& spec, int block_size, std::vector<SimResult>& out) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const SimSetup<T> setup = makeSetup<T>(spec);
  const GridView host = spec.view();
  const long first = spec.rangeBegin(), n = spec.rangeSize();
  DeviceGrid grid;
  grid.view = host;
  for (int a = 0; a < host.n_axes; ++a) grid.view.values[a] = grid.upload(host.values[a], host.count[a]);
  if (host.n_points > 0) grid.view.points = grid.upload(host.points, static_cast<size_t>(host.point_cols) * host.n_points);

  CudaRun run;
  if (block_size <= 0) {
    int min_grid = 0;
    check(cudaOccupancyMaxPotentialBlockSize(&min_grid, &block_size, sweepKernel<Law, T, Capacity>),
          "cudaOccupancyMaxPotentialBlockSize");
  }
  run.block_size = block_size;
  run.grid_size = (n + block_size - 1) / block_size;
  SimResult* dev_out = nullptr;
  check(cudaMalloc(&dev_out, n * sizeof(SimResult)), "cudaMalloc(results)");
  cudaEvent_t start, stop;
  check(cudaEventCreate(&start), "cudaEventCreate");
  check(cudaEventCreate(&stop), "cudaEventCreate");
  check(cudaEventRecord(start), "cudaEventRecord");
  sweepKernel<Law, T, Capacity><<<static_cast<unsigned>(run.grid_size), block_size>>>(setup, grid.view, first, n, dev_out);
  check(cudaGetLastError(), "kernel launch");
  check(cudaEventRecord(stop), "cudaEventRecord");
  check(cudaEventSynchronize(stop), "kernel");
  float ms = 0;
  check(cudaEventElapsedTime(&ms, start, stop), "cudaEventElapsedTime");
  run.kernel_s = ms / 1e3;
  out.resize(n);
  check(cudaMemcpy(out.data(), dev_out, n * sizeof(SimResult), cudaMemcpyDeviceToHost),
        "cudaMemcpy(results)");
  cudaFree(dev_out);
  cudaEventDestroy(start);
  cudaEventDestroy(stop);
  run.total_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return run;
}

template <typename T>
CudaRun launchPrecision(const SweepSpec& spec, int block_size, std::vector<SimResult>& out) {
  CudaRun run;
  aurora_control::withLaw(spec.law, [&](auto law) {
    constexpr aurora_control::LawType kLaw = decltype(law)::value;
    using aurora_control::kMediumHistory;
    using aurora_control::kShortHistory;
    // The tiers of withHistoryCapacity up to kMediumHistory: runCuda checks cudaMaxDelay().
    run = spec.max_delay < kShortHistory ? launch<kLaw, T, kShortHistory>(spec, block_size, out)
                                         : launch<kLaw, T, kMediumHistory>(spec, block_size, out);
  });
  return run;
}

}  // namespace

bool cudaCompiledIn() { return true; }

void selectCudaDevice(int local_rank) {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess || count == 0) {
    cudaGetLastError();  // clear: probeCudaDevice reports the error
    return;
  }
  cudaSetDevice(local_rank % count);
}

CudaDevice probeCudaDevice() {
  CudaDevice d;
  int count = 0;
  const cudaError_t err = cudaGetDeviceCount(&count);
  if (err != cudaSuccess) {
    d.error = std::string("cudaGetDeviceCount: ") + cudaGetErrorName(err) + " (" +
              cudaGetErrorString(err) + ")";
    return d;
  }
  if (count == 0) {
    d.error = "the CUDA runtime reports no device";
    return d;
  }
  int device = 0;  // the current one (selectCudaDevice under MPI)
  cudaGetDevice(&device);
  cudaDeviceProp prop;
  const cudaError_t perr = cudaGetDeviceProperties(&prop, device);
  if (perr != cudaSuccess) {
    d.error = std::string("cudaGetDeviceProperties: ") + cudaGetErrorString(perr);
    return d;
  }
  const cudaError_t ctx = cudaFree(nullptr);  // creates the context: the driver really works
  if (ctx != cudaSuccess) {
    d.error = std::string("creating a context on '") + prop.name + "': " + cudaGetErrorString(ctx);
    return d;
  }
  d.usable = true;
  d.name = prop.name;
  return d;
}

long cudaMaxDelay() { return aurora_control::kMediumHistory - 1; }

CudaRun runCuda(const SweepSpec& spec, int block_size, std::vector<SimResult>& out) {
  if (spec.max_delay > cudaMaxDelay()) {
    throw std::runtime_error("the cuda backend holds delays up to " + std::to_string(cudaMaxDelay()) +
                             " samples (each GPU thread keeps its history in local memory); this "
                             "sweep reaches " + std::to_string(spec.max_delay) + ": use --backend cpu");
  }
  if (spec.precision == Precision::kDouble) return launchPrecision<double>(spec, block_size, out);
  return launchPrecision<float>(spec, block_size, out);
}

}  // namespace aurora_sweep
