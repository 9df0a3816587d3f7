// Where the shared configuration lives (vehicles/, controllers/, tasks/,
// sweeps/ ...): $AURORA_CONFIG_DIR when set (a user's own tree), else the
// aurora_config package on the ROS package path, so the tools work from a
// devel space and from an install space alike (no source path compiled in).
#pragma once

#include <ros/package.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace aurora_common {

inline std::string configDir() {
  const char* env = std::getenv("AURORA_CONFIG_DIR");
  if (env != nullptr && *env != '\0') return env;
  const std::string path = ros::package::getPath("aurora_config");
  if (path.empty()) {
    throw std::runtime_error(
        "the configuration package 'aurora_config' is not on the ROS package path: source the "
        "workspace's setup.bash (devel/ or install/), or set AURORA_CONFIG_DIR to a config folder");
  }
  return path;
}

}  // namespace aurora_common
