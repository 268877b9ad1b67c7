#include "services/common/idempotency/first_answer_cache.h"

#include <gtest/gtest.h>

namespace semnav {
namespace {

TEST(FirstAnswerCacheTest, KeepsTheFirstAnswerAndForgetsTheOldestKey) {
  FirstAnswerCache<std::string> cache(2);
  cache.Remember("Submit:a", "first");
  cache.Remember("Submit:a", "second");  // a retry's answer never replaces the first
  EXPECT_EQ(cache.Find("Submit:a"), "first");
  cache.Remember("Submit:b", "b");
  cache.Remember("Submit:c", "c");  // over capacity: "a" goes
  EXPECT_EQ(cache.Find("Submit:a"), std::nullopt);
  EXPECT_EQ(cache.Find("Submit:b"), "b");
  EXPECT_EQ(cache.Find("Submit:c"), "c");
  EXPECT_EQ(cache.size(), 2u);
}

TEST(FirstAnswerCacheTest, EmptyKeysAndZeroCapacityRememberNothing) {
  FirstAnswerCache<int> cache(4);
  cache.Remember("", 1);
  EXPECT_EQ(cache.Find(""), std::nullopt);
  FirstAnswerCache<int> none(0);
  none.Remember("x", 1);
  EXPECT_EQ(none.Find("x"), std::nullopt);
}

}  // namespace
}  // namespace semnav
