#include "aurora_sweep/results.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace aurora_sweep {

namespace {

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

Counts countResults(const std::vector<SimResult>& results, long iterations) {
  Counts c;
  c.combinations = static_cast<long>(results.size());
  for (const SimResult& r : results) {
    const bool complete = r.steps >= iterations;
    for (int i = 0; i < 4; ++i) {
      const bool held = (r.ok >> i) & 1;
      c.passed[i] += held && complete;
      c.failed[i] += !held;
      c.not_reached[i] += held && !complete;
    }
    c.feasible += (r.ok >> 4) & 1;
    c.steps += r.steps;
  }
  return c;
}

void writeResultsCsv(const std::string& path, const SweepSpec& spec,
                     const std::vector<SimResult>& results) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write '" + path + "'");
  std::fprintf(f, "index,kp,kd,delay,ok1,ok2,ok3,ok4,feasible,iae,itae,iasc,steps,x,y,z\n");
  const GridView grid = spec.view();
  for (size_t i = 0; i < results.size(); ++i) {
    const SimResult& r = results[i];
    const Combination c = grid.decode(static_cast<long>(i));
    std::fprintf(f, "%zu,%.17g,%.17g,%ld,%d,%d,%d,%d,%d,%.17g,%.17g,%.17g,%d,%.9g,%.9g,%.9g\n", i,
                 c.kp, c.kd, c.delay, r.ok & 1, (r.ok >> 1) & 1, (r.ok >> 2) & 1, (r.ok >> 3) & 1,
                 (r.ok >> 4) & 1, r.iae, r.itae, r.iasc, r.steps, r.final_pos[0], r.final_pos[1],
                 r.final_pos[2]);
  }
  if (std::fclose(f) != 0) throw std::runtime_error("cannot finish writing '" + path + "'");
}

void writeSummaryJson(const std::string& path, const SweepSpec& spec, const RunInfo& info,
                      const Counts& counts) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write '" + path + "'");
  f.precision(10);
  const double sims_per_s = info.wall_time_s > 0 ? counts.combinations / info.wall_time_s : 0;
  const double steps_per_s = info.wall_time_s > 0 ? counts.steps / info.wall_time_s : 0;
  f << "{\n";
  f << "  \"name\": " << jsonString(spec.name) << ",\n";
  f << "  \"sweep_file\": " << jsonString(spec.file) << ",\n";
  f << "  \"sweep_file_text\": " << jsonString(readFile(spec.file)) << ",\n";
  f << "  \"vehicle_file\": " << jsonString(spec.vehicle_file) << ",\n";
  if (!spec.points_file.empty()) f << "  \"points_file\": " << jsonString(spec.points_file) << ",\n";
  f << "  \"controller\": " << jsonString(spec.controller) << ",\n";
  f << "  \"order\": [";
  for (size_t a = 0; a < spec.axes.size(); ++a) {
    f << (a ? ", " : "") << jsonString(paramName(spec.axes[a].param));
  }
  f << "],\n";
  f << "  \"combinations\": " << counts.combinations << ",\n";
  f << "  \"feasible\": " << counts.feasible << ",\n";
  // Per check 1-4: held through a complete run / failed / not reached (the
  // run stopped early at another check's failure while this one held).
  const auto list = [](const long v[4]) {
    return "[" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + ", " +
           std::to_string(v[3]) + "]";
  };
  f << "  \"checks\": {\"passed\": " << list(counts.passed) << ", \"failed\": " << list(counts.failed)
    << ", \"not_reached\": " << list(counts.not_reached) << "},\n";
  f << "  \"control_steps\": " << counts.steps << ",\n";
  f << "  \"early_stop\": " << (spec.early_stop ? "true" : "false") << ",\n";
  f << "  \"clamp_commands\": " << (spec.clamp_commands ? "true" : "false") << ",\n";
  f << "  \"backend\": " << jsonString(info.backend) << ",\n";
  f << "  \"device\": " << jsonString(info.device) << ",\n";
  f << "  \"precision\": " << jsonString(precisionName(spec.precision)) << ",\n";
  f << "  \"threads\": " << info.threads << ",\n";
  f << "  \"lanes\": " << info.lanes << ",\n";
  f << "  \"wall_time_s\": " << info.wall_time_s << ",\n";
  if (info.kernel_time_s >= 0) f << "  \"kernel_time_s\": " << info.kernel_time_s << ",\n";
  f << "  \"total_time_s\": " << info.wall_time_s << ",\n";
  f << "  \"simulations_per_s\": " << sims_per_s << ",\n";
  f << "  \"control_steps_per_s\": " << steps_per_s << ",\n";
  f << "  \"note\": " << jsonString(info.note) << "\n";
  f << "}\n";
  if (!f) throw std::runtime_error("cannot finish writing '" + path + "'");
}

}  // namespace aurora_sweep
