// A file option given as a shipped NAME (config/<folder>/NAME.yaml, as the
// launch files take them) or as a path (with a '/' or ending .yaml): the
// one rule of `flight` and of Python's aurora.simulate (which asks it
// through aurora._core).
#pragma once

#include <string>

namespace aurora_control {

inline bool isShippedName(const std::string& given) {
  const bool path = given.find('/') != std::string::npos ||
                    (given.size() > 5 && given.compare(given.size() - 5, 5, ".yaml") == 0);
  return !given.empty() && !path;
}

// config/<folder>/NAME.yaml for a NAME; a path (or "") as it is.
inline std::string shippedOrPath(const std::string& given, const std::string& config, const char* folder) {
  return isShippedName(given) ? config + "/" + folder + "/" + given + ".yaml" : given;
}

}  // namespace aurora_control
