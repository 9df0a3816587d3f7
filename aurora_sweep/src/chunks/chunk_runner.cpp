#include "chunk_runner.h"

#include <chrono>

#include "aurora_control/loop/closed_loop.h"
#include "aurora_sweep/cuda_backend.h"

namespace aurora_sweep {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void runRange(const SweepSpec& part, const BackendChoice& choice, std::vector<SimResult>& out,
              Progress& progress, ChunkWork& work) {
  if (choice.backend == "scalar") {
    runScalar(part, out, progress);
  } else if (choice.backend == "cpu") {
    runCpuBatch(part, choice.threads, out, progress);
  } else {
    const CudaRun run = runCuda(part, choice.block_size, out);
    progress.fetch_add(part.rangeSize(), std::memory_order_relaxed);
    work.kernel_s += run.kernel_s;
    work.grid_size = run.grid_size;
    work.block_size = run.block_size;
  }
}

}  // namespace

void runCombinations(const SweepSpec& part, const BackendChoice& choice, std::vector<SimResult>& out) {
  Progress progress{0};
  ChunkWork work;
  runRange(part, choice, out, progress, work);
}

ChunkWork runChunks(const SweepSpec& spec, const ChunkStore& store, ChunkSource& source,
                    const BackendChoice& choice, Progress& progress) {
  ChunkWork work;
  const ChunkPlan& plan = store.plan();
  SweepSpec part = spec;
  std::vector<SimResult> out;
  for (long c = source.next(); c >= 0; c = source.next()) {
    if (store.done(c)) {  // finished by an earlier run: counted in progress already
      ++work.resumed_chunks;
      continue;
    }
    part.range_begin = plan.begin(c);
    part.range_end = plan.end(c);
    const Clock::time_point t0 = Clock::now();
    runRange(part, choice, out, progress, work);
    const Clock::time_point t1 = Clock::now();
    store.write(c, out);
    work.compute_s += std::chrono::duration<double>(t1 - t0).count();
    work.write_s += since(t1);
    ++work.computed_chunks;
    work.computed_combinations += part.rangeSize();
    for (const SimResult& r : out) work.computed_steps += r.steps;
  }
  return work;
}

Counts mergeChunks(const SweepSpec& spec, const ChunkStore& store,
                   const std::vector<ResultsWriter*>& writers, const ChunkConsumer& consume,
                   std::vector<double>* writer_s, std::map<std::string, long>* chunks_by) {
  const long iterations = spec.iterations();
  Counts counts(checkCount(spec.formation()));
  std::vector<SimResult> chunk;
  std::vector<double> seconds(writers.size(), 0.0);
  for (long c = 0; c < store.plan().count(); ++c) {
    std::string by;
    store.read(c, chunk, &by);
    if (chunks_by) ++(*chunks_by)[by];
    addCounts(counts, chunk, iterations);
    for (size_t w = 0; w < writers.size(); ++w) {
      const Clock::time_point t0 = Clock::now();
      writers[w]->append(store.plan().begin(c), chunk);
      seconds[w] += since(t0);
    }
    if (consume) consume(store.plan().begin(c), chunk);
  }
  for (size_t w = 0; w < writers.size(); ++w) {
    const Clock::time_point t0 = Clock::now();
    writers[w]->close();
    seconds[w] += since(t0);
  }
  if (writer_s) *writer_s = seconds;
  return counts;
}

}  // namespace aurora_sweep
