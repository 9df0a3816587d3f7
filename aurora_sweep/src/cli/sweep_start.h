// Everything that can refuse a sweep, checked before anything is written:
// the sweep file, the backend (the CUDA device, its launch limits), the MPI
// ranks' agreement, the output folder and the plan (time, bytes, free
// space). Under MPI every rank takes part in each decision, so a rank that
// cannot start stops every rank with the same message instead of leaving
// the others waiting in a collective call.
#pragma once

#include <string>
#include <vector>

#include "aurora_sweep/results.h"
#include "aurora_sweep/sweep_spec.h"
#include "../chunks/mpi_ranks.h"
#include "sweep_options.h"

namespace aurora_sweep {

struct StartCheck {
  int status = 0;       // the exit status; 0: go
  std::string message;  // why not (without the "sweep: " prefix)
};

struct Start {
  SweepSpec spec;
  RunInfo info;
  long chunk_size = 0;
  std::string computed_by;           // what computes this rank's chunks
  std::string run_computed_by;       // the whole run's (ranks agree, or "mixed: ...")
  std::vector<std::string> created;  // folders made for --out (removed on a refusal)
};

// Loads the sweep, picks the backend and checks that it can run here.
StartCheck loadAndChooseBackend(const Options& opt, const MpiRanks* mpi, Start& start);
// Creates --out and says what the sweep will cost; refuses what cannot fit.
StartCheck prepareOutput(const Options& opt, bool lead, Start& start);
// Collective under MPI: every rank's check reaches rank 0, which prints
// each refusal with its rank; every rank gets the worst status. Without MPI
// it prints the refusal. Returns the status (0: go).
int agreeToStart(const MpiRanks* mpi, const StartCheck& mine);
// Collective under MPI: the ranks' backends must be the same (the chunks
// of a sweep agree to rounding only across backends) unless
// --mixed-backends (rank 0 says why); sets start.run_computed_by. Returns
// the status (0: go).
int agreeOnBackend(const Options& opt, const MpiRanks* mpi, Start& start);

// --output auto: CSV for spreadsheets up to a million rows, HDF5 beyond.
std::string outputFormat(const Options& opt, long combinations);

}  // namespace aurora_sweep
