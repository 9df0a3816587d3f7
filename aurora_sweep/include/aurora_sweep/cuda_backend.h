// The `cuda` backend: one simulation per GPU thread, each thread decoding
// its own combination from its index and running the same templates
// (simulation.h) as the CPU. Built only where nvcc is found; otherwise a stub
// reports that the build has no CUDA.
#pragma once

#include <string>
#include <vector>

#include "aurora_sweep/simulation.h"
#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

struct CudaDevice {
  bool usable = false;
  std::string name;   // device name when usable
  std::string error;  // why not, with the CUDA runtime's own error text
};

struct CudaRun {
  int block_size = 0;
  long grid_size = 0;
  double kernel_s = 0;  // kernel only (CUDA events)
  double total_s = 0;   // allocation, transfers and kernel
};

bool cudaCompiledIn();
// Largest delay [samples] the kernel's per-thread history holds.
long cudaMaxDelay();
CudaDevice probeCudaDevice();
// MPI ranks on a multi-GPU node: rank `local_rank` uses device local_rank mod
// the device count (before probeCudaDevice). No-op without devices or CUDA.
void selectCudaDevice(int local_rank);

// block_size 0 picks one (occupancy API). Throws std::runtime_error with the
// CUDA error text on failure.
CudaRun runCuda(const SweepSpec& spec, int block_size, std::vector<SimResult>& out);

}  // namespace aurora_sweep
