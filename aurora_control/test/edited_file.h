// Tests of refusals: what a call is refused with, and a shipped config
// file with one edit read by the reader under test; "" when it loads.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "aurora_common/refusal_text.h"

namespace aurora_tests {

// What `run()` is refused with (its ConfigError's text), or "" when it runs.
template <class Run>
std::string configRefusal(Run&& run) {
  try {
    run();
  } catch (const aurora_common::ConfigError& e) {
    return e.what();
  }
  return "";
}

// A copy of config/`file` with `from` replaced by `to` (its path; "" when
// `from` is not in the file).
inline std::string editedConfigFile(const std::string& file, const std::string& from, const std::string& to) {
  std::ifstream in(std::string(AURORA_CONFIG_DIR) + "/" + file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find(from);
  if (at == std::string::npos) return "";
  text.replace(at, from.size(), to);
  const std::string path = ::testing::TempDir() + "/edited.yaml";
  std::ofstream(path) << text;
  return path;
}

// config/`file` with `from` replaced by `to`, read by read(path, config dir).
template <class Read>
std::string refusalOfEditedFile(const std::string& file, const std::string& from, const std::string& to, Read&& read) {
  const std::string path = editedConfigFile(file, from, to);
  if (path.empty()) return "the test's edit '" + from + "' is not in the file";
  return configRefusal([&] { read(path, AURORA_CONFIG_DIR); });
}

}  // namespace aurora_tests
