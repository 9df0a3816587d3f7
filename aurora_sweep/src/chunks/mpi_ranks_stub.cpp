// Built where MPI is not found: a sweep started by mpirun is refused (every
// rank would otherwise run the whole sweep into the same folder).
#include <stdexcept>

#include "mpi_ranks.h"

namespace aurora_sweep {

bool MpiRanks::compiledIn() { return false; }

MpiRanks::MpiRanks(int*, char***) {
  throw std::runtime_error("started as an MPI rank, but this build has no MPI (install libopenmpi-dev "
                           "and rebuild), or run without mpirun");
}

MpiRanks::~MpiRanks() = default;
std::string MpiRanks::host() const { return ""; }
std::unique_ptr<ChunkSource> MpiRanks::chunks(long) { return nullptr; }
void MpiRanks::barrier() const {}
int MpiRanks::broadcast(int value) const { return value; }
std::string MpiRanks::broadcast(const std::string& value) const { return value; }
int MpiRanks::maxOverRanks(int value) const { return value; }
nlohmann::json MpiRanks::gather(const nlohmann::json&) const { return nullptr; }

}  // namespace aurora_sweep
