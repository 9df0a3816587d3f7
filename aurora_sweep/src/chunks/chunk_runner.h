// A sweep run as chunks (chunk_store.h): each chunk computed on the chosen
// backend and written as soon as it is done; then the finished chunks read
// back in index order into the outputs. The same code serves one process
// and MPI ranks; only the source of chunk numbers differs.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/chunk_store.h"
#include "aurora_sweep/results.h"

namespace aurora_sweep {

// Hands out chunk numbers; -1 when none is left.
class ChunkSource {
 public:
  virtual ~ChunkSource() = default;
  virtual long next() = 0;
};

// One process: every chunk in order.
class SequentialChunks : public ChunkSource {
 public:
  explicit SequentialChunks(long count) : count_(count) {}
  long next() override { return next_ < count_ ? next_++ : -1; }

 private:
  long count_, next_ = 0;
};

struct BackendChoice {
  std::string backend;  // scalar | cpu | cuda
  int threads = 1;
  int block_size = 0;
};

struct ChunkWork {
  long computed_chunks = 0, resumed_chunks = 0;  // of the chunks this process was handed
  long computed_combinations = 0;
  long long computed_steps = 0;                  // model steps of the computed chunks
  double compute_s = 0, write_s = 0;             // simulating vs writing chunk files
  double kernel_s = 0;                           // CUDA kernels
  long grid_size = 0;
  int block_size = 0;
};

// Computes the combinations of `part`'s range on the chosen backend (the
// sweep plan's calibration).
void runCombinations(const SweepSpec& part, const BackendChoice& choice, std::vector<SimResult>& out);

// Computes each chunk `source` hands out that `store` has not got, writing
// it at once. Throws std::runtime_error (backend or file errors).
ChunkWork runChunks(const SweepSpec& spec, const ChunkStore& store, ChunkSource& source,
                    const BackendChoice& choice, Progress& progress);

// Sees each chunk's results during the merge (e.g. --rviz's copy, the delay
// monotony count).
using ChunkConsumer = std::function<void(long first, const std::vector<SimResult>& results)>;

// Reads every chunk in index order into `writers`, `consume` (optional) and
// the counts; `writer_s` (optional) gets the seconds spent in each writer,
// `chunks_by` (optional) the number of chunks each backend computed.
Counts mergeChunks(const SweepSpec& spec, const ChunkStore& store,
                   const std::vector<ResultsWriter*>& writers, const ChunkConsumer& consume,
                   std::vector<double>* writer_s = nullptr, std::map<std::string, long>* chunks_by = nullptr);

}  // namespace aurora_sweep
