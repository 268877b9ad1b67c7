#include "services/modelproxy/core/response_cache.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

const absl::Time kT0 = absl::FromUnixSeconds(1000);

CachedAnswer Answer(const std::string& text) {
  return CachedAnswer{BackendReply{text, "m", {}, false, "", std::nullopt}, "b"};
}

TEST(ModelProxyResponseCacheTest, EvictsTheLeastRecentlyUsedEntry) {
  ResponseCache cache({/*capacity=*/2, absl::Minutes(10)});
  cache.Put("a", Answer("A"), kT0);
  cache.Put("b", Answer("B"), kT0);
  ASSERT_TRUE(cache.Get("a", kT0));  // "a" is now the most recent
  cache.Put("c", Answer("C"), kT0);  // evicts "b"
  EXPECT_FALSE(cache.Get("b", kT0));
  ASSERT_TRUE(cache.Get("a", kT0));
  EXPECT_EQ(cache.Get("a", kT0)->reply.text, "A");
  EXPECT_EQ(cache.Get("c", kT0)->backend, "b");
  EXPECT_EQ(cache.size(), 2);
}

TEST(ModelProxyResponseCacheTest, EntriesExpireAfterTheTtl) {
  ResponseCache cache({10, absl::Seconds(60)});
  cache.Put("k", Answer("v"), kT0);
  EXPECT_TRUE(cache.Get("k", kT0 + absl::Seconds(59)));
  EXPECT_FALSE(cache.Get("k", kT0 + absl::Seconds(60)));
  EXPECT_EQ(cache.size(), 0);
}

TEST(ModelProxyResponseCacheTest, ZeroCapacityDisablesTheCache) {
  ResponseCache cache({0, absl::Seconds(60)});
  cache.Put("k", Answer("v"), kT0);
  EXPECT_FALSE(cache.Get("k", kT0));
}

}  // namespace
}  // namespace semnav::modelproxy
