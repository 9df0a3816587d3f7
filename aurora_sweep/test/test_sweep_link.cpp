// A sweep over a link (sweep file 'link:', docs/links.md): an ideal link
// file changes nothing; over a lossy link every CPU backend gives the same
// bits, the draws follow the combination (not the chunk), and the link is
// part of the sweep's definition.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "aurora_sweep/chunk_store.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;
using namespace aurora_sweep::test;

namespace {

// The small grid of the backend tests (80 combinations), over links/NAME.yaml.
SweepSpec smallGrid(const std::string& link) {
  std::string text = readText(std::string(AURORA_SWEEP_TEST_DIR) + "/data/small_grid.yaml");
  if (!link.empty()) text += "  link: links/" + link + ".yaml\n";
  return loadSweepFile(writeTemp("small_grid_link_" + link + ".yaml", text), configDir());
}

long differing(const std::vector<SimResult>& a, const std::vector<SimResult>& b) {
  long n = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(SimResult)) != 0;
  return n + static_cast<long>(a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

}  // namespace

TEST(SweepLink, AnIdealLinkFileChangesNothing) {
  const SweepSpec plain = smallGrid(""), ideal = smallGrid("ideal");
  EXPECT_TRUE(ideal.link.ideal());
  EXPECT_EQ(definitionHash(plain), definitionHash(ideal));
  EXPECT_EQ(differing(runOn("scalar", plain), runOn("scalar", ideal)), 0);
}

TEST(SweepLink, EveryCpuBackendGivesTheSameBitsOverALossyLink) {
  const SweepSpec lossy = smallGrid("wifi_congested");
  ASSERT_FALSE(lossy.link.ideal());
  const std::vector<SimResult> scalar = runOn("scalar", lossy);
  EXPECT_EQ(differing(scalar, runOn("cpu", lossy)), 0);
  EXPECT_EQ(differing(scalar, runOn(widestIsa(), lossy)), 0);
  // Not vacuous: the link changed most runs.
  EXPECT_GT(differing(scalar, runOn("scalar", smallGrid(""))), 40);
  EXPECT_NE(definitionHash(lossy), definitionHash(smallGrid("")));
  EXPECT_NE(definitionHash(lossy), definitionHash(smallGrid("wifi_lab")));
}

TEST(SweepLink, DrawsFollowTheCombinationNotTheChunk) {
  const SweepSpec full = smallGrid("wifi_lab");
  SweepSpec part = full;
  part.range_begin = 37, part.range_end = 61;
  const std::vector<SimResult> all = runOn("scalar", full);
  std::vector<SimResult> some;
  Progress progress{0};
  runScalar(part, some, progress);
  ASSERT_EQ(some.size(), 24u);
  EXPECT_EQ(differing(std::vector<SimResult>(all.begin() + 37, all.begin() + 61), some), 0);
}

TEST(SweepLink, ALinkBeyondTheHistoryOrMissingIsRefused) {
  const std::string grid = "sweep:\n  parameters:\n    kp: 0.5\n    kd: 0.85\n    delay: {values: [0, 1790]}\n";
  const std::string wide = writeTemp("wide_link.yaml", "link:\n  uplink: {jitter: {kind: uniform, max: 300}}\n");
  EXPECT_NE(refusal(grid + "  link: " + wide + "\n").find("needs 2090 samples of history with the sweep's largest "
                                                          "delay 1790: accepted up to 2047"),
            std::string::npos)
      << refusal(grid + "  link: " + wide + "\n");
  EXPECT_NE(refusal(grid + "  link: links/nowhere.yaml\n").find("link file"), std::string::npos);
}

TEST(SweepLink, TheShippedLinkStudyIsTheThesisGridOverACongestedLink) {
  const SweepSpec s = loadSweepFile(configDir() + "/sweeps/positioning_delay_wifi_congested.yaml", configDir());
  EXPECT_EQ(s.size(), 65536);
  EXPECT_FALSE(s.link.ideal());
  EXPECT_NE(s.link_file.find("links/wifi_congested.yaml"), std::string::npos);
  EXPECT_EQ(s.max_delay, 63);
}
