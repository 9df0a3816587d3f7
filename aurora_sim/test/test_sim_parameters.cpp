// The simulator's parameter table (sim_parameters.h) is the one source of
// its node's parameters: docs/parameters.md's simulator reference is the
// table's (regenerate it from the failure's text), and the rows keep their
// ranges (a take-off must leave the ground).
#include <gtest/gtest.h>

#include "aurora_common/testing/doc_section.h"
#include "aurora_sim/sim_parameters.h"

using namespace aurora_sim;

TEST(SimParameters, DocsReferenceIsTheTables) {
  EXPECT_EQ(aurora_common::docSection(AURORA_PARAMETER_DOC, "sim-parameter-reference"), simParameterReference())
      << "docs/parameters.md's simulator reference differs from sim_parameters.h: put this between the markers";
}

TEST(SimParameters, RowsAreInTheirOrderAndKeepTheirRanges) {
  EXPECT_STREQ(kSimParameterTable[kSimRowMode].name, "mode");
  EXPECT_STREQ(kSimParameterTable[kSimRowPublishClock].name, "publish_clock");
  const aurora_common::ParameterSpec& takeoff = kSimParameterTable[kSimRowTakeoffAltitude];
  EXPECT_EQ(takeoff.min, kLandedAltitude);
  EXPECT_TRUE(takeoff.min_excluded);  // a take-off to the landed height would never end
  EXPECT_TRUE(kSimParameterTable[kSimRowCmdTimeout].min_excluded);
  for (const aurora_common::ParameterSpec& row : kSimParameterTable) EXPECT_EQ(row.live, nullptr) << row.name;
}
