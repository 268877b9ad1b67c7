#include "services/common/place_prior/place_prior.h"

#include <gtest/gtest.h>

namespace semnav {
namespace {

const std::string kPriorJson = std::string(SEMNAV_SHARED_DATA_DIR) +
                               "/object-priors/conceptnet_atlocation_coco80/conceptnet-data.json";

TEST(PlacePriorTest, LoadsTheConceptNetFile) {
  const auto prior = PlacePrior::Load(kPriorJson);
  ASSERT_TRUE(prior.ok()) << prior.status();
  EXPECT_EQ(prior->object_count(), 66u);  // SOURCE.txt: 66 of the 80 COCO classes
  EXPECT_EQ(prior->edge_count(), 738u);   // 740 edges minus two bare "/c/en/a" (fork, horse)
  // toilet: bathroom 7.2111 of total weight 29.0394 (14 edges, no places merged).
  EXPECT_NEAR(prior->Probability("toilet", "bathroom"), 0.248320225274467, 1e-9);
  EXPECT_DOUBLE_EQ(prior->Affinity("toilet", "bathroom"), 1.0);
  EXPECT_NEAR(prior->Affinity("toilet", "house"), 4.0 / 7.211102550927979, 1e-9);
  EXPECT_EQ(prior->Probability("toilet", "kitchen"), 0.0);
  EXPECT_TRUE(prior->Knows("dining table"));  // file key "dining_table"
  EXPECT_FALSE(prior->Knows("helmet"));
  EXPECT_EQ(prior->TopPlaces("toilet", 2)[1].first, "house");
}

TEST(PlacePriorTest, RelatednessIsTheCosineOfPlaceDistributions) {
  const auto prior = PlacePrior::Load(kPriorJson);
  ASSERT_TRUE(prior.ok());
  EXPECT_NEAR(prior->Relatedness("toilet", "toilet"), 1.0, 1e-12);
  EXPECT_GT(prior->Relatedness("fork", "knife"), 0.6);  // kitchen, drawers, table
  EXPECT_EQ(prior->Relatedness("fork", "toilet"), 0.0);
  EXPECT_EQ(prior->Relatedness("fork", "helmet"), 0.0);
  EXPECT_NEAR(prior->Relatedness("fork", "knife"), prior->Relatedness("knife", "fork"), 1e-12);
}

TEST(PlacePriorTest, MissingFileIsNotFound) {
  EXPECT_EQ(PlacePrior::Load("/nonexistent.json").status().code(), absl::StatusCode::kNotFound);
}

}  // namespace
}  // namespace semnav
