// The registry test's build of the nodes (test/CMakeLists.txt, registry_*):
// the vehicles it adds to the shipped list (vehicle_type.h reads this file
// where AURORA_EXTRA_VEHICLES names it). One line per vehicle.
#pragma once

#include "aurora_common/named_list.h"
#include "test_quad/test_quad.h"

namespace aurora_sim {
using ExtraVehicles = aurora_common::TypeList<registry::TestQuad>;
}
