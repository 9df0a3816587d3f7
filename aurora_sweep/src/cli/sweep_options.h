// The sweep program's options, parsed by parseOptions (sweep_options.cpp).
#pragma once

#include <string>

namespace aurora_sweep {

struct Options {
  std::string config, out, backend = "auto", precision, config_dir;  // empty: configDir()
  std::string output = "auto", rows = "all";
  int threads = 0;
  int block_size = 0;
  long chunk_size = 0;  // 0: chunkSizeFor()
  bool plots = true, rviz = false, quiet = false, overwrite = false;
  bool ignore_free_space = false;
  bool mixed_backends = false;  // MPI: accept ranks on different backends (chunks record theirs)
};

// The options of the command line; --help prints the usage and exits 0, a
// refused value prints one line naming it and the usage, and exits 2.
Options parseOptions(int argc, char** argv);

}  // namespace aurora_sweep
