// The controller's parameters (loop/controller_parameters.h) are the one
// source: each live law's gain rows as the law declares them, then the
// parameter table's (parameter_table.h); docs/parameters.md's parameter
// reference is theirs (regenerate it from the failure's text).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "aurora_common/testing/doc_section.h"
#include "aurora_control/loop/controller_parameters.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/params/parameter_table.h"
#include "aurora_control/law/ardrone2/underactuated_law.h"

using namespace aurora_control;

// Every gain of a law the node changes live is a parameter row, declared by
// the law alone (its gainRow): name, default, range; then the table's rows.
TEST(ParameterTable, TheLiveLawsGainsAreTheControllersFirstRows) {
  const std::vector<ParameterSpec>& rows = controllerParameters();
  size_t r = 0;
  int laws = 0;
  forEachLiveGainLaw([&](auto law) {
    using Law = decltype(law);
    ++laws;
    for (int i = 0; i < Law::kGainCount; ++i, ++r) {
      const GainRow g = Law::gainRow(i);
      ASSERT_LT(r, rows.size());
      EXPECT_STREQ(rows[r].name, g.name);
      EXPECT_STREQ(rows[r].live, g.name);
      EXPECT_TRUE(rows[r].default_value == g.preset || (std::isnan(g.preset) && std::isnan(rows[r].default_value)))
          << g.name;
      EXPECT_EQ(rows[r].min, g.min) << g.name;
      EXPECT_EQ(rows[r].max, g.max) << g.name;
      EXPECT_EQ(std::string(rows[r].doc).find(std::string(Law::name()) + " law: "), 0u) << rows[r].doc;
      EXPECT_EQ(controllerLiveSetting(g.name), &rows[r]);
    }
  });
  EXPECT_EQ(laws, 2);  // the AR.Drone's two: the laws whose every gain is a row
  ASSERT_EQ(rows.size(), r + kParameterRows);
  for (int i = 0; i < kParameterRows; ++i) EXPECT_STREQ(rows[r + i].name, kParameterTable[i].name);
  // The underactuated law's defaults are its own (the spec's), the PD law has none (a study names both).
  const UnderactuatedGains<double> defaults = UnderactuatedGains<double>::defaults();
  for (int i = 0; i < 2 * kAxes; ++i) {
    EXPECT_EQ(controllerLiveSetting(underactuatedGainName(i))->default_value, underactuatedGain(defaults, i));
  }
  EXPECT_TRUE(std::isnan(controllerLiveSetting("kp")->default_value));
  EXPECT_EQ(controllerLiveSetting("delay_samples"), &rows[r + kRowDelaySamples]);
}

TEST(ParameterTable, TheDelayHistoryFollowsTheDelayRow) {
  EXPECT_EQ(kMaxDelaySamples, 2047);  // the histories are sized from it (kDelayHistory)
  EXPECT_EQ(kDelayHistory, kMaxDelaySamples + 1);
}

TEST(ParameterTable, DocsReferenceIsTheControllers) {
  EXPECT_EQ(aurora_common::docSection(AURORA_PARAMETER_DOC, "parameter-reference"), controllerParameterReference())
      << "docs/parameters.md's reference differs from the controller's parameters (parameter_table.h and the live "
         "laws' gain rows): put this between the markers";
}
