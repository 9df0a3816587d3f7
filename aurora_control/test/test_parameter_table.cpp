// The parameter table (parameter_table.h) is the one source: the laws' own
// defaults and the names they are read by equal its rows, and docs/parameters.md's
// parameter reference is the table's (regenerate it from the failure's text).
#include <gtest/gtest.h>

#include "aurora_common/testing/doc_section.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/params/parameter_table.h"
#include "aurora_control/law/underactuated_law.h"

using namespace aurora_control;

TEST(ParameterTable, UnderactuatedRowsAreTheLawsGainsAndDefaults) {
  const UnderactuatedGains<double> defaults = UnderactuatedGains<double>::defaults();
  for (int i = 0; i < 2 * kAxes; ++i) {
    const ParameterSpec& row = kParameterTable[kRowFirstUnderactuatedGain + i];
    EXPECT_STREQ(row.name, underactuatedGainName(i));
    EXPECT_EQ(row.default_value, underactuatedGain(defaults, i)) << row.name;
    EXPECT_EQ(row.min, kUnderactuatedGainMin) << row.name;
    EXPECT_EQ(row.max, kUnderactuatedGainMax) << row.name;
  }
  EXPECT_EQ(kRowMode, kRowFirstUnderactuatedGain + 2 * kAxes);  // the 12 gains, then the node's rows
}

TEST(ParameterTable, BothPdGainsShareOneRange) {
  EXPECT_EQ(kParameterTable[kRowKd].min, kPdGainMin);
  EXPECT_EQ(kParameterTable[kRowKd].max, kPdGainMax);
  EXPECT_EQ(kMaxDelaySamples, 2047);  // the histories are sized from it (kDelayHistory)
  EXPECT_EQ(kDelayHistory, kMaxDelaySamples + 1);
}

TEST(ParameterTable, DocsReferenceIsTheTables) {
  EXPECT_EQ(aurora_common::docSection(AURORA_PARAMETER_DOC, "parameter-reference"), parameterReference())
      << "docs/parameters.md's reference differs from parameter_table.h: put this between the markers";
}
