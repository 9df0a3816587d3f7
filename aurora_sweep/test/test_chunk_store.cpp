// The chunk store: chunk ranges, atomic chunk files read back, a damaged or
// foreign chunk refused, another sweep's folder refused, old outputs removed.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "aurora_sweep/chunk_store.h"
#include "aurora_sweep/sweep_file.h"

#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

std::string freshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "'").c_str());
  return dir;
}

std::vector<SimResult> fakeResults(long n, int seed) {
  std::vector<SimResult> r(static_cast<size_t>(n));
  for (long i = 0; i < n; ++i) {
    r[i].iae = seed + i * 0.5;
    r[i].steps = static_cast<int>(i);
    r[i].ok = static_cast<unsigned char>(i % 32);
  }
  return r;
}

}  // namespace

TEST(ChunkPlan, CoversTheIndexSpaceOnce) {
  const ChunkPlan plan{80, 7};
  EXPECT_EQ(plan.count(), 12);
  long covered = 0;
  for (long c = 0; c < plan.count(); ++c) {
    EXPECT_EQ(plan.begin(c), covered);
    covered = plan.end(c);
  }
  EXPECT_EQ(covered, 80);
  EXPECT_EQ(plan.end(11) - plan.begin(11), 3);
}

TEST(ChunkStore, WritesReadsAndResumes) {
  const SweepSpec spec = loadSweepFile(test::dataDir() + "/small_grid.yaml", test::configDir());
  const std::string dir = freshDir("chunks_resume");
  const ChunkPlan plan{spec.size(), 7};
  {
    ChunkStore store(dir, spec, plan, false, "scalar");
    EXPECT_FALSE(store.resumed());
    store.write(3, fakeResults(7, 3));
    store.write(11, fakeResults(3, 11));
    EXPECT_THROW(store.write(0, fakeResults(5, 0)), std::logic_error);  // wrong length
  }
  ChunkStore again(dir, spec, plan, false, "scalar");  // the same command after a crash
  EXPECT_TRUE(again.resumed());
  EXPECT_EQ(again.doneCount(), 2);
  EXPECT_TRUE(again.done(3));
  EXPECT_FALSE(again.done(4));
  std::vector<SimResult> back;
  again.read(11, back);
  ASSERT_EQ(back.size(), 3u);
  EXPECT_EQ(back[2].iae, 12.0);
  EXPECT_EQ(back[2].steps, 2);
  // A torn or foreign file is refused, not read as results.
  std::ofstream(dir + "/progress/chunk_00000004.bin") << "garbage";
  EXPECT_THROW(again.read(4, back), std::runtime_error);
}

TEST(ChunkStore, AnotherSweepIsRefusedAndOldOutputsGo) {
  const SweepSpec spec = loadSweepFile(test::dataDir() + "/small_grid.yaml", test::configDir());
  SweepSpec other = spec;
  other.early_stop = !spec.early_stop;
  EXPECT_NE(definitionHash(spec), definitionHash(other));
  const std::string dir = freshDir("chunks_refuse");
  { ChunkStore store(dir, spec, ChunkPlan{spec.size(), 7}, false, "scalar"); }
  try {
    ChunkStore refused(dir, other, ChunkPlan{spec.size(), 7}, false, "scalar");
    FAIL() << "another sweep accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("holds another sweep"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(hashText(definitionHash(other))), std::string::npos) << e.what();
    // Which sweep is there, by name, not only by hash.
    EXPECT_NE(std::string(e.what()).find("another sweep ('" + spec.name + "', in progress"), std::string::npos)
        << e.what();
  }
  // The same sweep in other chunks is another layout of the progress: refused too.
  EXPECT_THROW(ChunkStore(dir, spec, ChunkPlan{spec.size(), 8}, false, "scalar"), std::runtime_error);
  // --overwrite: a fresh run; the earlier run's outputs are gone first.
  std::ofstream(dir + "/check3_region.png") << "old";
  std::ofstream(dir + "/notes.txt") << "the user's own file";
  ChunkStore replaced(dir, other, ChunkPlan{spec.size(), 7}, true, "scalar");
  EXPECT_FALSE(replaced.resumed());
  EXPECT_FALSE(exists(dir + "/check3_region.png"));
  EXPECT_TRUE(exists(dir + "/notes.txt"));
}

// A run killed on one backend and resumed on another would mix numbers that
// agree to rounding only: refused, naming the backend to resume with.
TEST(ChunkStore, ResumingWithAnotherBackendIsRefused) {
  const SweepSpec spec = loadSweepFile(test::dataDir() + "/small_grid.yaml", test::configDir());
  const std::string dir = freshDir("chunks_backend");
  const ChunkPlan plan{spec.size(), 7};
  { ChunkStore store(dir, spec, plan, false, "scalar"); store.write(0, fakeResults(7, 0)); }
  try {
    ChunkStore other(dir, spec, plan, false, "cpu (avx2)");
    FAIL() << "resumed with another backend";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("computed so far by the scalar backend: resuming with cpu (avx2) would "
                                         "mix"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("resume with --backend scalar"), std::string::npos) << e.what();
  }
  ChunkStore same(dir, spec, plan, false, "scalar");
  EXPECT_TRUE(same.resumed());
  EXPECT_TRUE(same.done(0));
}
