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
  int device = -1;    // the device's number when usable
};

// The device of an MPI rank (selectCudaDevice).
struct DeviceChoice {
  bool ok = true;    // false: cudaSetDevice failed (note says why)
  int devices = 0;   // on this host
  int device = -1;   // chosen; -1 without devices
  std::string note;  // set when ranks share a GPU, or on failure
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
// Why the kernel cannot hold this sweep's delays ("" when it can); needs no device.
std::string cudaDelayProblem(const SweepSpec& spec);
// A usable device has a context and loads this build's kernel.
CudaDevice probeCudaDevice();
// MPI ranks on a node: local rank r of `local_size` uses device r mod the
// device count (before probeCudaDevice); says when ranks share a GPU.
DeviceChoice selectCudaDevice(int local_rank, int local_size);
// Before anything is written: why `spec` cannot launch with `block_size`
// (0: the occupancy API's) on the current device: its delays, the block size
// against the kernel's registers, the local memory every resident thread
// reserves against the free memory. "" when it can.
std::string cudaLaunchProblem(const SweepSpec& spec, int block_size);
// Threads the device keeps resident for this sweep's kernel (occupancy API).
long cudaResidentThreads(const SweepSpec& spec, int block_size);

// block_size 0 picks one (occupancy API). Throws std::runtime_error with the
// CUDA error text on failure.
CudaRun runCuda(const SweepSpec& spec, int block_size, std::vector<SimResult>& out);

}  // namespace aurora_sweep
