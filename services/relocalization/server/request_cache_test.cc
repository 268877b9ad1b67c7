#include "services/relocalization/server/request_cache.h"

#include <gtest/gtest.h>

namespace semnav::relocalization {
namespace {

TEST(RelocRequestCacheTest, KeepsFirstAnswerAndForgetsOldestBeyondCapacity) {
  RequestCache<int> cache(2);
  cache.Remember("a", 1);
  cache.Remember("a", 9);  // the first answer stays
  cache.Remember("b", 2);
  EXPECT_EQ(cache.Find("a"), 1);
  cache.Remember("c", 3);  // evicts "a"
  EXPECT_FALSE(cache.Find("a").has_value());
  EXPECT_EQ(cache.Find("b"), 2);
  EXPECT_EQ(cache.Find("c"), 3);
}

TEST(RelocRequestCacheTest, EmptyIdIsNeverRemembered) {
  RequestCache<int> cache(4);
  cache.Remember("", 1);
  EXPECT_FALSE(cache.Find("").has_value());
}

}  // namespace
}  // namespace semnav::relocalization
