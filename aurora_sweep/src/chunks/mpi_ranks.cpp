#include "mpi_ranks.h"

// The C API only (the deprecated C++ bindings would need libmpi_cxx).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace aurora_sweep {

namespace {

// Chunk numbers from a counter in rank 0's window (passive target: rank 0
// need not take part while the others draw).
class SharedChunks : public ChunkSource {
 public:
  explicit SharedChunks(long count) : count_(count) {
    MPI_Win_allocate(sizeof(long), sizeof(long), MPI_INFO_NULL, MPI_COMM_WORLD, &counter_, &win_);
    *counter_ = 0;
    MPI_Barrier(MPI_COMM_WORLD);  // every counter is zero before anyone draws
  }
  ~SharedChunks() override { MPI_Win_free(&win_); }

  long next() override {
    const long one = 1;
    long drawn = 0;
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, win_);
    MPI_Fetch_and_op(&one, &drawn, MPI_LONG, 0, 0, MPI_SUM, win_);
    MPI_Win_unlock(0, win_);
    return drawn < count_ ? drawn : -1;
  }

 private:
  long count_;
  long* counter_ = nullptr;
  MPI_Win win_;
};

}  // namespace

bool MpiRanks::compiledIn() { return true; }

MpiRanks::MpiRanks(int* argc, char*** argv) {
  int provided = 0;
  // Only the main thread calls MPI; the cpu backend's threads do not.
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm host;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &host);
  MPI_Comm_rank(host, &local_rank_);
  MPI_Comm_size(host, &local_size_);
  MPI_Comm_free(&host);
}

MpiRanks::~MpiRanks() { MPI_Finalize(); }

std::string MpiRanks::host() const {
  char name[MPI_MAX_PROCESSOR_NAME];
  int n = 0;
  MPI_Get_processor_name(name, &n);
  return std::string(name, static_cast<size_t>(n));
}

std::unique_ptr<ChunkSource> MpiRanks::chunks(long count) {
  return std::unique_ptr<ChunkSource>(new SharedChunks(count));
}

void MpiRanks::barrier() const { MPI_Barrier(MPI_COMM_WORLD); }

int MpiRanks::broadcast(int value) const {
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

std::string MpiRanks::broadcast(const std::string& value) const {
  int length = broadcast(static_cast<int>(value.size()));
  std::string text = rank_ == 0 ? value : std::string(static_cast<size_t>(length), '\0');
  MPI_Bcast(&text[0], length, MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
}

int MpiRanks::maxOverRanks(int value) const {
  int result = value;
  MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return result;
}

nlohmann::json MpiRanks::gather(const nlohmann::json& mine) const {
  const std::string text = mine.dump();
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(static_cast<size_t>(size_)), offsets(static_cast<size_t>(size_));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank_ == 0) {
    int total = 0;
    for (int r = 0; r < size_; ++r) offsets[r] = total, total += lengths[r];
    all.resize(static_cast<size_t>(total));
  }
  MPI_Gatherv(text.data(), length, MPI_CHAR, &all[0], lengths.data(), offsets.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  if (rank_ != 0) return nullptr;
  nlohmann::json ranks = nlohmann::json::array();
  for (int r = 0; r < size_; ++r) ranks.push_back(nlohmann::json::parse(all.substr(offsets[r], lengths[r])));
  return ranks;
}

}  // namespace aurora_sweep
