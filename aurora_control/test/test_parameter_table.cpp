// The parameter table (parameter_table.h) is the one source: the laws' own
// defaults and the names they are read by equal its rows, and docs/parameters.md's
// parameter reference is the table's (regenerate it from the failure's text).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

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
  std::ifstream in(AURORA_PARAMETER_DOC);
  ASSERT_TRUE(in.good()) << AURORA_PARAMETER_DOC;
  std::stringstream text;
  text << in.rdbuf();
  const std::string readme = text.str(), begin = "<!-- parameter-reference:begin -->\n",
                    end = "<!-- parameter-reference:end -->";
  const size_t a = readme.find(begin), b = readme.find(end);
  ASSERT_NE(a, std::string::npos) << "docs/parameters.md lacks the marker " << begin;
  ASSERT_NE(b, std::string::npos) << "docs/parameters.md lacks the marker " << end;
  EXPECT_EQ(readme.substr(a + begin.size(), b - a - begin.size()), parameterReference())
      << "docs/parameters.md's reference differs from parameter_table.h: put this between the markers";
}
