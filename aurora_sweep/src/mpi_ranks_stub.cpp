// Built where MPI is not found: a sweep started by mpirun is refused (every
// rank would otherwise run the whole sweep into the same folder).
#include <cstdlib>
#include <stdexcept>

#include "mpi_ranks.h"

namespace aurora_sweep {

bool MpiRanks::launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"}) {
    const char* v = std::getenv(name);
    if (v && *v) return true;
  }
  return false;
}

bool MpiRanks::compiledIn() { return false; }

MpiRanks::MpiRanks(int*, char***) {
  throw std::runtime_error("started as an MPI rank, but this build has no MPI (install libopenmpi-dev "
                           "and rebuild), or run without mpirun");
}

MpiRanks::~MpiRanks() = default;
int MpiRanks::localRank() const { return 0; }
std::string MpiRanks::host() const { return ""; }
std::unique_ptr<ChunkSource> MpiRanks::chunks(long) { return nullptr; }
void MpiRanks::barrier() const {}
int MpiRanks::broadcast(int value) const { return value; }
int MpiRanks::maxOverRanks(int value) const { return value; }
nlohmann::json MpiRanks::gather(const nlohmann::json&) const { return nullptr; }

}  // namespace aurora_sweep
