// Stand-in for the CUDA backend in builds without nvcc.
#include <stdexcept>

#include "aurora_sweep/cuda_backend.h"

namespace aurora_sweep {

bool cudaCompiledIn() { return false; }

CudaDevice probeCudaDevice() {
  CudaDevice d;
  d.error = "this build has no CUDA backend (nvcc was not found when it was built; "
            "install the CUDA toolkit and rebuild)";
  return d;
}

long cudaMaxDelay() { return 0; }

std::string cudaDelayProblem(const SweepSpec&) { return probeCudaDevice().error; }

DeviceChoice selectCudaDevice(int, int) { return DeviceChoice(); }

std::string cudaLaunchProblem(const SweepSpec&, int) { return probeCudaDevice().error; }

long cudaResidentThreads(const SweepSpec&, int) { return 0; }

CudaRun runCuda(const SweepSpec&, int, std::vector<SimResult>&) {
  throw std::runtime_error(probeCudaDevice().error);
}

}  // namespace aurora_sweep
