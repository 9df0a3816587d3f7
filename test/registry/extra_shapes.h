// The registry test's build of the formation node (test/CMakeLists.txt,
// registry_formation): the shapes it adds to the shipped list (shapes.h
// reads this file where AURORA_EXTRA_SHAPES names it). One line per shape.
#pragma once

#include "aurora_common/named_list.h"
#include "three_abreast/three_abreast_entry.h"

namespace aurora_control {
using ExtraShapes = aurora_common::TypeList<registry::ThreeAbreastEntry>;
}
