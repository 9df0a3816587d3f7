// The shipped studies (config/sweeps/) cut to fewer samples, for tests.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "aurora_sweep/sweep_file.h"

namespace aurora_sweep {
namespace test {

inline std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// config/sweeps/NAME.yaml with `samples_line` replaced by `samples` (relative
// names resolve in config/).
inline SweepSpec shippedStudy(const std::string& name, const std::string& samples_line, long samples,
                              Precision precision) {
  const std::string config = AURORA_CONFIG_DIR;
  std::string text = readText(config + "/sweeps/" + name + ".yaml");
  const size_t at = text.find(samples_line);
  EXPECT_NE(at, std::string::npos) << name;
  if (at != std::string::npos) text.replace(at, samples_line.size(), "samples: " + std::to_string(samples));
  SweepSpec spec = loadSweepFile(writeTemp(name + "_small.yaml", text), config);
  spec.precision = precision;
  return spec;
}

inline SweepSpec study13(long samples, Precision p = Precision::kDouble) {
  return shippedStudy("underactuated_13", "samples: 65536", samples, p);
}
inline SweepSpec robustness(long samples, Precision p = Precision::kDouble) {
  return shippedStudy("robustness", "samples: 4096", samples, p);
}

}  // namespace test
}  // namespace aurora_sweep
