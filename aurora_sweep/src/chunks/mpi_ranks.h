// MPI ranks, when the sweep is started by mpirun or srun (OpenMPI from
// Debian; built only where MPI is found: mpi_ranks_stub.cpp otherwise). The
// ranks share the output folder (a shared file system on a cluster): rank 0
// prepares it, every rank takes chunk numbers from one counter in rank 0's
// memory (MPI one-sided fetch-and-add: uneven, early-stopping chunks balance
// themselves) and writes the chunks it computes; rank 0 then merges them, so
// the result is the single-process one byte for byte.
#pragma once

#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "chunk_runner.h"

namespace aurora_sweep {

class MpiRanks {
 public:
  // True when this process was started as an MPI rank (mpirun, srun): the
  // launchers' environment, so a plain run never initialises MPI. The same
  // rule with or without MPI built in (the stub refuses such a launch).
  static bool launchedByMpi() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"}) {
      const char* v = std::getenv(name);
      if (v && *v) return true;
    }
    return false;
  }
  static bool compiledIn();

  // MPI_Init; throws std::runtime_error when this build has no MPI.
  MpiRanks(int* argc, char*** argv);
  ~MpiRanks();  // MPI_Finalize
  MpiRanks(const MpiRanks&) = delete;
  MpiRanks& operator=(const MpiRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Rank among the ranks on this host, and their number, from
  // MPI_Comm_split_type(MPI_COMM_TYPE_SHARED): any launcher.
  int localRank() const { return local_rank_; }
  int localSize() const { return local_size_; }
  std::string host() const;

  // The shared chunk counter (collective: every rank calls it).
  std::unique_ptr<ChunkSource> chunks(long count);
  void barrier() const;
  // Rank 0's value to every rank; the largest value of any rank to every rank.
  int broadcast(int value) const;
  std::string broadcast(const std::string& value) const;
  int maxOverRanks(int value) const;
  // Every rank's facts, at rank 0 (an array in rank order); others get null.
  nlohmann::json gather(const nlohmann::json& mine) const;

 private:
  int rank_ = 0, size_ = 1, local_rank_ = 0, local_size_ = 1;
};

}  // namespace aurora_sweep
