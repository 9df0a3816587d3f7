// The sweep program's command line (Boost.Program_options): what each option
// accepts, the help text, and the refusals (one line naming the option, the
// value given and what is accepted, then the usage).
#include <boost/program_options.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "sweep_options.h"

#include "aurora_control/formation/shapes.h"

namespace po = boost::program_options;

namespace aurora_sweep {

namespace {

// The shapes' names come from their list (aurora_control/formation/shapes.h).
std::string about() {
  return "usage: sweep --config FILE|NAME --out DIR [options]\n"
         "\n"
         "Runs every combination of a sweep file (a law's gains x delay x model factors x\n"
         "link values, on any task; or a formation's robots' delays x formation gains x link\n"
         "values (a shape's law) with `formation:` (" + aurora_control::knownShapeNames() + "); a\n"
         "grid, a sampling design or a points file) and writes DIR/results.csv (one row per\n"
         "combination), DIR/summary.json and DIR/*.png.\n"
         "\n"
         "options";
}

const char* kNotes =
    "\n"
    "The cpu backend picks at run time the widest SIMD build this CPU runs;\n"
    "AURORA_SWEEP_SIMD=avx512|avx2|sse4_2|none forces one (none: no SIMD lanes).\n";

// The numbers are read as text, so that a refusal quotes what was given.
struct Numbers {
  std::string threads, block_size, chunk_size;
};

po::options_description describe(Options& o, Numbers& n) {
  po::options_description d(about(), 100, 50);
  d.add_options()
      ("config", po::value(&o.config)->value_name("FILE"),
       "sweep file (YAML), or a shipped NAME (config/sweeps/NAME.yaml), e.g. positioning_delay (the thesis "
       "grid) or underactuated_13 (13 parameters)")
      ("out", po::value(&o.out)->value_name("DIR"), "output folder (created; must be writable)")
      ("backend", po::value(&o.backend)->value_name("NAME"),
       "scalar (one simulation at a time, one thread), cpu (SIMD lanes on all cores), cuda (one "
       "simulation per GPU thread), or auto (cuda when a device works, else cpu). Default: auto")
      ("precision", po::value(&o.precision)->value_name("P"),
       "double or float (default: the sweep file's, else double)")
      ("threads", po::value(&n.threads)->value_name("N"), "cpu backend threads (default: all cores)")
      ("block-size", po::value(&n.block_size)->value_name("N"),
       "cuda threads per block, up to what the kernel's registers allow (checked before the run; "
       "default: chosen by occupancy)")
      ("config-dir", po::value(&o.config_dir)->value_name("DIR"),
       "where vehicles/ and tasks/ named by the sweep file are found (default: the aurora_config "
       "package on the ROS package path)")
      ("output", po::value(&o.output)->value_name("FORMAT"),
       "csv (results.csv), hdf5 (results.h5, columns; h5py reads it), both, or none (summary.json "
       "and plots only). Default: csv up to 1,000,000 combinations, hdf5 above")
      ("rows", po::value(&o.rows)->value_name("WHICH"),
       "all (default) or feasible: which combinations the results hold")
      ("chunk-size", po::value(&n.chunk_size)->value_name("N"),
       "combinations per chunk (default: a 64th of the sweep, within [4096, 262144]): each finished "
       "chunk is written to DIR/progress/ at once; the same command on the same DIR after a crash "
       "computes only the missing chunks")
      ("overwrite", po::bool_switch(&o.overwrite), "replace another sweep's results in DIR (otherwise refused)")
      ("mixed-backends", po::bool_switch(&o.mixed_backends),
       "MPI: accept ranks computing on different backends (e.g. auto on hosts with and without a "
       "GPU); each chunk records its backend")
      ("ignore-free-space", po::bool_switch(&o.ignore_free_space),
       "run even when the estimated bytes exceed the free space (the plan printed at the start says both)")
      ("no-plots", "skip the PNG plots")
      ("rviz", po::bool_switch(&o.rviz),
       "publish the feasible set as a latched MarkerArray (/sweep/feasible, frame 'sweep') and keep "
       "running until Ctrl-C")
      ("quiet", po::bool_switch(&o.quiet), "no progress on stderr")
      ("help,h", "this text");
  return d;
}

[[noreturn]] void usageError(const std::string& msg, const po::options_description& d) {
  std::cerr << "sweep: " << msg << "\n\n" << d << kNotes;
  std::exit(2);
}

void requireWord(const std::string& flag, const std::string& v, const std::vector<std::string>& accepted,
                 const po::options_description& d) {
  if (std::find(accepted.begin(), accepted.end(), v) != accepted.end()) return;
  std::string list;
  for (const std::string& a : accepted) list += (list.empty() ? "" : ", ") + a;
  usageError(flag + " '" + v + "' is unknown: accepted " + list, d);
}

long wholeNumber(const std::string& flag, const std::string& v, long max, const po::options_description& d) {
  char* end = nullptr;
  const long n = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || n < 1 || n > max) {
    usageError(flag + " '" + v + "' is invalid: accepted a whole number in [1, " + std::to_string(max) + "]", d);
  }
  return n;
}

// The values as given: words from their lists, numbers in their ranges.
void check(Options& o, const Numbers& n, const po::options_description& d) {
  requireWord("--backend", o.backend, {"scalar", "cpu", "cuda", "auto"}, d);
  if (!o.precision.empty()) requireWord("--precision", o.precision, {"double", "float"}, d);
  if (o.output != "auto") requireWord("--output", o.output, {"csv", "hdf5", "both", "none"}, d);
  requireWord("--rows", o.rows, {"all", "feasible"}, d);
  if (!n.threads.empty()) o.threads = static_cast<int>(wholeNumber("--threads", n.threads, 65536, d));
  if (!n.block_size.empty()) o.block_size = static_cast<int>(wholeNumber("--block-size", n.block_size, 65536, d));
  if (o.block_size > 1024) {
    usageError("--block-size " + std::to_string(o.block_size) + " is invalid: CUDA blocks hold at most 1024 "
               "threads (a kernel may allow fewer: checked against its registers before the run)", d);
  }
  if (!n.chunk_size.empty()) o.chunk_size = wholeNumber("--chunk-size", n.chunk_size, 1L << 30, d);
  if (o.config.empty()) usageError("--config FILE (or a shipped NAME) is required", d);
  if (o.out.empty()) usageError("--out DIR is required", d);
  if (o.threads == 0) o.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

Options parseOptions(int argc, char** argv) {
  Options o;
  Numbers n;
  const po::options_description d = describe(o, n);
  // ROS remapping arguments (__name:=..., from rosrun or roslaunch) are
  // ros::init's (with --rviz): set aside, anything else unknown is refused.
  std::vector<std::string> args, ros_args;
  for (int i = 1; i < argc; ++i) (std::string(argv[i]).rfind("__", 0) == 0 ? ros_args : args).push_back(argv[i]);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(args).options(d).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    usageError(e.what(), d);
  }
  if (vm.count("help")) {
    std::cout << d << kNotes;
    std::exit(0);
  }
  o.plots = vm.count("no-plots") == 0;
  check(o, n, d);
  return o;
}

}  // namespace aurora_sweep
