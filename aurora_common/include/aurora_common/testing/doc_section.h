// For tests: the text of a docs page between its markers
// (<!-- NAME:begin -->\n ... <!-- NAME:end -->), where a generated copy lives
// (a parameter reference); the tests compare it with its source.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace aurora_common {

inline std::string docSection(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  if (!in.good()) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str(), begin = "<!-- " + name + ":begin -->\n", end = "<!-- " + name + ":end -->";
  const size_t a = doc.find(begin), b = doc.find(end);
  if (a == std::string::npos || b == std::string::npos || b < a) {
    throw std::runtime_error(path + " lacks the markers " + begin + "and " + end);
  }
  return doc.substr(a + begin.size(), b - a - begin.size());
}

}  // namespace aurora_common
