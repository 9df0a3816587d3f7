#include "sweep_plan.h"

#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>

#include "aurora_sweep/results.h"

namespace aurora_sweep {

namespace {

// The nearest folder of `path` that exists (the output folder may not yet).
std::string existingFolder(std::string path) {
  while (!path.empty() && access(path.c_str(), F_OK) != 0) {
    const size_t slash = path.find_last_of('/');
    path = slash == std::string::npos ? "" : path.substr(0, slash);
  }
  return path.empty() ? "." : path;
}

// Runs the first combinations until 0.2 s have passed (or all ran): the
// rate, and the results of the largest run for sizing a results row.
double calibrate(const SweepSpec& spec, const BackendChoice& choice, long& ran, std::vector<SimResult>& out) {
  SweepSpec part = spec;
  double rate = 0;
  for (long n = std::min(64L, spec.size());; n = std::min(n * 4, spec.size())) {
    part.range_begin = 0;
    part.range_end = n;
    const auto t0 = std::chrono::steady_clock::now();
    runCombinations(part, choice, out);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rate = s > 0 ? n / s : 0, ran = n;
    if (s >= 0.2 || n == spec.size() || n >= (1L << 20)) return rate;
  }
}

// Bytes of a results.csv row for these results, measured by writing them.
double csvRowBytes(const SweepSpec& spec, const std::vector<SimResult>& sample) {
  char name[] = "/tmp/aurora_sweep_rowXXXXXX";
  const int fd = mkstemp(name);
  if (fd < 0) return 0;
  close(fd);
  {
    std::unique_ptr<ResultsWriter> w = openCsvWriter(name, spec, false);
    w->append(0, sample);
    w->close();
  }
  std::ifstream in(name, std::ios::ate | std::ios::binary);
  const double bytes = static_cast<double>(in.tellg());
  std::remove(name);
  return sample.empty() ? 0 : bytes / static_cast<double>(sample.size());
}

std::string bytesText(double b) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (b >= 1000 && u < 6) b /= 1000, ++u;
  char buf[32];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", b, units[u]);
  return buf;
}

std::string durationText(double s) {
  char buf[48];
  if (s < 1) std::snprintf(buf, sizeof buf, "under 1 s");
  else if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
  else if (s < 172800) std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  else if (s < 3.15e9) std::snprintf(buf, sizeof buf, "%.0f days", s / 86400);
  else std::snprintf(buf, sizeof buf, "%.2g years", s / 3.15576e7);
  return buf;
}

std::string grouped(long n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace

std::string counted(long n, const std::string& singular, const std::string& plural) {
  return grouped(n) + " " + (n == 1 ? singular : plural);
}

std::string runCount(long n, long repeats) {
  return repeats > 1 ? counted(n, "run", "runs") : counted(n, "combination", "combinations");
}

SweepPlan planSweep(const SweepSpec& spec, const BackendChoice& choice, const std::string& out,
                    const std::string& format, long chunk_size) {
  SweepPlan p;
  p.combinations = spec.size();
  p.repeats = spec.repeats;
  std::vector<SimResult> sample;
  p.rate = calibrate(spec, choice, p.calibrated, sample);
  p.seconds = p.rate > 0 ? p.combinations / p.rate : 0;
  p.chunks = ChunkPlan{p.combinations, chunk_size}.count();
  p.chunk_bytes = static_cast<uint64_t>(p.combinations) * sizeof(SimResult) + static_cast<uint64_t>(p.chunks) * 64;
  const double row = csvRowBytes(spec, sample);
  const double rows = static_cast<double>(p.combinations);
  double results = 0;
  if (format == "csv" || format == "both") results += row * rows;
  // HDF5 keeps the same columns in binary: a CSV row's bytes bound it.
  // --output none writes no results (the summary and plots only).
  if (format == "hdf5" || format == "both") results += row * rows;
  p.results_bytes = static_cast<uint64_t>(results);
  p.volume = existingFolder(out);
  struct statvfs fs;
  if (statvfs(p.volume.c_str(), &fs) == 0) p.free_bytes = static_cast<uint64_t>(fs.f_bavail) * fs.f_frsize;
  return p;
}

std::string planText(const SweepPlan& p) {
  char rate[160];
  std::snprintf(rate, sizeof rate, "%.0f sims/s", p.rate);
  return runCount(p.combinations, p.repeats) + " in " + counted(p.chunks, "chunk", "chunks") +
         ": " + (p.seconds < 1 ? "" : "about ") + durationText(p.seconds) + " at " + rate + " (measured on the first " +
         grouped(p.calibrated) + "), writes about " + bytesText(double(p.neededBytes())) + " (chunk files " +
         bytesText(double(p.chunk_bytes)) + ", results " + bytesText(double(p.results_bytes)) + "); " +
         bytesText(double(p.free_bytes)) + " free in " + p.volume;
}

}  // namespace aurora_sweep
