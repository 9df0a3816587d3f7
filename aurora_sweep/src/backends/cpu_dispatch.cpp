// The `cpu` backend's choice of instruction set, at run time: the widest
// build of the SIMD engine (batch_isa.cpp) this CPU runs, or the one named by
// AURORA_SWEEP_SIMD (sse4_2, avx2, avx512, native, none = threads without
// SIMD lanes; auto = the default). A binary built anywhere runs anywhere: no
// engine code runs unless the CPU has its instructions. Compiled with the
// baseline flags, like everything outside the engine libraries.
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "aurora_sweep/backends.h"
#include "../lanes/batch_isa.h"

namespace aurora_sweep {

namespace {

struct Isa {
  const char* key;
  bool (*supported)();
  void (*run)(const SweepSpec&, int, std::vector<SimResult>&, Progress&);
  int (*lanes)(Precision);
  const char* (*name)();
};

#if defined(__x86_64__) || defined(__i386__)
// __builtin_cpu_supports also checks that the OS saves the wide registers.
bool hasSse42() { return __builtin_cpu_supports("sse4.2"); }
bool hasAvx2() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }
bool hasAvx512() {
  return hasAvx2() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512vl");
}
#endif
// -march=native (opt-in, AURORA_SWEEP_NATIVE): runs where it was built.
bool builtHere() { return true; }

int noLanes(Precision) { return 1; }
const char* threadsName() { return "threads without SIMD lanes"; }

// Widest first: the first one the CPU supports is the default.
std::vector<Isa> builtIsas() {
  std::vector<Isa> isas;
#ifdef AURORA_SWEEP_ISA_NATIVE
  isas.push_back({"native", builtHere, isa_native::run, isa_native::lanes, isa_native::name});
#endif
#ifdef AURORA_SWEEP_ISA_AVX512
  isas.push_back({"avx512", hasAvx512, isa_avx512::run, isa_avx512::lanes, isa_avx512::name});
#endif
#ifdef AURORA_SWEEP_ISA_AVX2
  isas.push_back({"avx2", hasAvx2, isa_avx2::run, isa_avx2::lanes, isa_avx2::name});
#endif
#ifdef AURORA_SWEEP_ISA_SSE4_2
  isas.push_back({"sse4_2", hasSse42, isa_sse4_2::run, isa_sse4_2::lanes, isa_sse4_2::name});
#endif
  isas.push_back({"none", builtHere, runThreadedScalar, noLanes, threadsName});
  return isas;
}

std::string keysOf(const std::vector<Isa>& isas, bool supported_only) {
  std::string keys;
  for (const Isa& isa : isas) {
    if (supported_only && !isa.supported()) continue;
    keys += (keys.empty() ? "" : ", ") + std::string(isa.key);
  }
  return keys;
}

// `wanted`: a build's key, or empty / "auto" for the widest the CPU runs.
Isa choose(const std::string& wanted, const std::string& source) {
  const std::vector<Isa> isas = builtIsas();
  if (wanted.empty() || wanted == "auto") {
    for (const Isa& isa : isas) {
      if (isa.supported()) return isa;
    }
  }
  for (const Isa& isa : isas) {
    if (wanted != isa.key) continue;
    if (isa.supported()) return isa;
    throw std::runtime_error(source + wanted + ": this CPU lacks those instructions; it runs: " +
                             keysOf(isas, true));
  }
  throw std::runtime_error(source + wanted + " is not one of the builds: " + keysOf(isas, false) +
                           ", auto");
}

// Chosen once per process (the environment is read once).
const Isa& chosen() {
  static const Isa isa = [] {
    const char* env = std::getenv("AURORA_SWEEP_SIMD");
    return choose(env ? env : "", "AURORA_SWEEP_SIMD=");
  }();
  return isa;
}

void runOn(const Isa& isa, const SweepSpec& spec, int threads, std::vector<SimResult>& out, Progress& progress) {
  isa.run(spec, threads < 1 ? 1 : threads, out, progress);
}

}  // namespace

void runCpuBatch(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                 Progress& progress) {
  runOn(chosen(), spec, threads, out, progress);
}

int cpuBatchLanes(Precision precision) { return chosen().lanes(precision); }

std::string cpuBatchArch(Precision) {
  return std::string(chosen().name()) + " (" + chosen().key + ", chosen at run time)";
}

std::vector<CpuIsa> cpuBatchIsas() {
  std::vector<CpuIsa> out;
  for (const Isa& isa : builtIsas()) out.push_back({isa.key, isa.name(), isa.supported()});
  return out;
}

void runCpuBatchOn(const std::string& key, const SweepSpec& spec, int threads,
                   std::vector<SimResult>& out, Progress& progress) {
  runOn(choose(key, "instruction set "), spec, threads, out, progress);
}

}  // namespace aurora_sweep
