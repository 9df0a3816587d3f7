// Built where libhdf5 is not found: the HDF5 output is refused with a message.
#include <stdexcept>

#include "aurora_sweep/results.h"

namespace aurora_sweep {

bool hdf5Available() { return false; }

std::unique_ptr<ResultsWriter> openHdf5Writer(const std::string& path, const SweepSpec&, bool) {
  throw std::runtime_error("cannot write '" + path + "': this build has no HDF5 (install libhdf5-dev "
                           "and rebuild), use --output csv");
}

}  // namespace aurora_sweep
