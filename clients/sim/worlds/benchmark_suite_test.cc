#include "clients/sim/worlds/benchmark_suite.h"

#include <gtest/gtest.h>

#include <map>

#include "clients/sim/core/world_yaml.h"

namespace semnav::sim {
namespace {

TEST(SimBenchmarkSuiteTest, AllSourcesWrittenAndLoadable) {
  const auto suite = BuildBenchmarkSuite(1, SEMNAV_SHARED_DATA_DIR);
  ASSERT_TRUE(suite.ok()) << suite.status();
  std::map<std::string, int> per_suite;
  for (const SuiteWorld& w : *suite) {
    ++per_suite[w.suite];
    EXPECT_EQ(w.world.starts.size(), 5u) << w.world.name;
    EXPECT_FALSE(w.world.objects.empty()) << w.world.name;
  }
  EXPECT_EQ(per_suite["indoor"], 8);
  EXPECT_EQ(per_suite["outdoor"], 3);
  EXPECT_EQ(per_suite["flyroll"], 2);
  EXPECT_EQ(per_suite["houseexpo"], 2);
  EXPECT_EQ(per_suite["fr079"], 1);
  const std::string out = ::testing::TempDir() + "/sim_suite";
  ASSERT_TRUE(WriteBenchmarkSuite(*suite, out).ok());
  for (const auto& [name, count] : per_suite) {
    const auto loaded = LoadSuite(out + "/" + name);
    ASSERT_TRUE(loaded.ok()) << loaded.status();
    EXPECT_EQ(static_cast<int>(loaded->size()), count);
  }
}

TEST(SimBenchmarkSuiteTest, SeedFixesOutdoorScenes) {
  const auto a = BuildBenchmarkSuite(5, SEMNAV_SHARED_DATA_DIR);
  const auto b = BuildBenchmarkSuite(5, SEMNAV_SHARED_DATA_DIR);
  ASSERT_TRUE(a.ok() && b.ok());
  for (size_t i = 0; i < a->size(); ++i) {
    EXPECT_EQ(WorldToYaml((*a)[i].world), WorldToYaml((*b)[i].world)) << (*a)[i].world.name;
  }
}

}  // namespace
}  // namespace semnav::sim
