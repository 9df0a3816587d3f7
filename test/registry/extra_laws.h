// The registry test's build of the nodes (test/CMakeLists.txt, registry_*):
// the laws it adds to the shipped list (other_laws.h reads this file where
// AURORA_EXTRA_LAWS names it). One line per law.
#pragma once

#include "aurora_common/named_list.h"
#include "test_quad/test_quad_pd.h"

namespace aurora_control {
using ExtraLaws = aurora_common::TypeList<registry::TestQuadPd>;
}
