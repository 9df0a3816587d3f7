// The shipped configuration folder (config/) the control core's gtests read,
// defined once for the files of test_control_core (one batch of its unity
// build holds several of them).
#pragma once

#include <string>

namespace aurora_tests {

static const std::string kConfig = AURORA_CONFIG_DIR;

}  // namespace aurora_tests
