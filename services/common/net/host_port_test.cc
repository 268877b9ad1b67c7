#include "services/common/net/host_port.h"

#include <gtest/gtest.h>

namespace semnav {
namespace {

TEST(SplitHostPort, SplitsAtTheLastColon) {
  const std::optional<HostPort> v4 = SplitHostPort("0.0.0.0:50051");
  ASSERT_TRUE(v4.has_value());
  EXPECT_EQ(v4->host, "0.0.0.0");
  EXPECT_EQ(v4->port, "50051");
  const std::optional<HostPort> v6 = SplitHostPort("[::1]:8080");
  ASSERT_TRUE(v6.has_value());
  EXPECT_EQ(v6->host, "[::1]");
  EXPECT_EQ(v6->BareHost(), "::1");
  EXPECT_EQ(v6->port, "8080");
}

TEST(SplitHostPort, AnEmptyHostAndNoColon) {
  const std::optional<HostPort> any = SplitHostPort(":9000");
  ASSERT_TRUE(any.has_value());
  EXPECT_EQ(any->host, "");
  EXPECT_EQ(any->port, "9000");
  EXPECT_FALSE(SplitHostPort("localhost").has_value());
  EXPECT_EQ((HostPort{"[::", "1"}).BareHost(), "[::");  // unbalanced brackets stay as written
}

}  // namespace
}  // namespace semnav
