// A sweep's index space in chunks, and the output folder that keeps the
// finished ones (DIR/progress/), so that a run that dies (SIGKILL, a node
// lost) is resumed by the same command: only missing chunks are computed,
// and the result equals an uninterrupted run. Each chunk file is written
// under a temporary name and renamed: a chunk is either whole or absent.
// The folder records a hash of the sweep's definition; another sweep is
// refused there. ROS-free.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "aurora_sweep/simulation.h"
#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

struct ChunkPlan {
  long total = 0;  // combinations of the sweep
  long size = 1;   // combinations per chunk (the last may be shorter)
  long count() const { return (total + size - 1) / size; }
  long begin(long chunk) const { return chunk * size; }
  long end(long chunk) const { return begin(chunk) + size < total ? begin(chunk) + size : total; }
};

// CRC-32 (Boost.CRC) of the resolved definition: vehicle, task, criteria,
// axes or points, options and precision (not the file's formatting).
uint32_t definitionHash(const SweepSpec& spec);
std::string hashText(uint32_t hash);  // 8 hex digits

// The files a sweep writes into its output folder (results, summary, plots).
const std::vector<std::string>& sweepOutputFiles();

class ChunkStore {
 public:
  // Prepares `out_dir` for this sweep and plan:
  // - DIR/progress/ of the same definition: resume (its chunks count as done);
  // - a folder holding another sweep's progress or summary: refused with
  //   std::runtime_error naming both hashes, unless `overwrite`;
  // - otherwise a fresh run: the sweep's own old outputs (sweepOutputFiles())
  //   are removed first, so a reused folder never mixes old and new files.
  // `computed_by` (the backend, e.g. "scalar", "cpu (avx512)") is recorded:
  // resuming with another is refused, since backends agree to rounding only
  // and mixed chunks would equal no uninterrupted run.
  ChunkStore(const std::string& out_dir, const SweepSpec& spec, const ChunkPlan& plan, bool overwrite,
             const std::string& computed_by);

  // What computes this process's chunks, recorded in each chunk file
  // (default: `computed_by`; an MPI rank of a --mixed-backends run: its own).
  void setChunkComputedBy(const std::string& who) { chunk_by_ = who; }

  bool resumed() const { return resumed_; }
  const ChunkPlan& plan() const { return plan_; }
  uint32_t hash() const { return hash_; }
  bool done(long chunk) const;
  long doneCount() const;
  long doneCombinations() const;  // combinations in the chunks already done
  // Atomic: a temporary file renamed into place. Throws std::runtime_error.
  void write(long chunk, const std::vector<SimResult>& results) const;
  // Throws std::runtime_error when the chunk file is missing or damaged.
  // `computed_by` (optional) gets what computed the chunk.
  void read(long chunk, std::vector<SimResult>& results, std::string* computed_by = nullptr) const;
  // After the final outputs are written: the progress folder goes.
  void removeProgress() const;

 private:
  std::string chunkPath(long chunk) const;
  void openOrCreate(bool overwrite);

  std::string out_dir_, progress_dir_, name_, computed_by_, chunk_by_;
  ChunkPlan plan_;
  uint32_t hash_;
  bool resumed_ = false;
};

}  // namespace aurora_sweep
