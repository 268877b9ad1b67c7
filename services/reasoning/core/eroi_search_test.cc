#include "services/reasoning/core/eroi_search.h"

#include <cmath>

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

// 5 x 4 x 1 EROIs of 2 m, centres (0..8, 0..6, 0): N = 20, prior 1/20.
EroiSearchConfig Config() {
  EroiSearchConfig config;
  config.grid.min = Eigen::Vector3d(0, 0, 0);
  config.grid.delta = 2.0;
  config.grid.nx = 4;
  config.grid.ny = 3;
  config.grid.nz = 0;
  return config;
}

int Flat(const EroiSearch& search, int i, int j) { return search.grid().Flatten({i, j, 0}); }

TEST(GatewayEroiSearchTest, VlmCodesAreStrongEvidenceWithinOneEdgeByHand) {
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("red mug", Config());
  ASSERT_TRUE(search.ok()) << search.status();
  EXPECT_DOUBLE_EQ(search->values().prior(), 0.05);
  // C2A = (i 2, j 1, k 0) = centre (4, 2, 0); r = delta = 2 m covers it and its 4 side
  // neighbours (m = 5): s = (1 - 1/5) 0.05 + 1/5 = 0.24 (eq. 20).
  const EroiEvidence evidence =
      search->OnVlmAnswer("Code: C2A, Description: a mug on the kitchen shelf\nnoise");
  EXPECT_EQ(evidence.codes_used, 1);
  EXPECT_TRUE(evidence.due.empty());  // 1 of theta = 3
  for (auto [i, j] : std::vector<std::pair<int, int>>{{2, 1}, {1, 1}, {3, 1}, {2, 0}, {2, 2}}) {
    EXPECT_NEAR(search->values().value(Flat(*search, i, j)), 0.24, 1e-12) << i << "," << j;
  }
  EXPECT_NEAR(search->values().value(Flat(*search, 3, 0)), 0.05, 1e-12);  // 2.83 m away
  EXPECT_EQ(search->OnVlmAnswer("Code: Z9Z, Description: off the grid").codes_used, 0);
}

TEST(GatewayEroiSearchTest, ThirdRecordInARegionUnitTriggersTheRegionScoreByHand) {
  EroiSearchConfig seed_literal = Config();
  seed_literal.evidence_once_per_code = false;  // C2A's second answer is evidence again
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("red mug", seed_literal);
  ASSERT_TRUE(search.ok());
  search->OnVlmAnswer("Code: C2A, Description: shelf");
  search->OnVlmAnswer("Code: C2A, Description: counter");
  const EroiEvidence third =
      search->OnVlmAnswer("Code: D1A, Description: sink");  // (3, 0): same 2x2 unit
  ASSERT_EQ(third.due.size(), 1u);
  const RegionDue& region = third.due[0];
  ASSERT_EQ(region.erois.size(), 4u);  // i 2..3, j 0..1
  EXPECT_EQ(region.descriptions.size(), 3u);
  EXPECT_NE(search->RegionPrompt(region).find("[red mug]"), std::string::npos);

  // (2, 1): evidence from C2A twice (0.05 -> 0.24 -> 0.392) and from D1A at (6, 0), 2.83 m
  // away: not in its N_r. Region score 4 over k = 4 EROIs (eq. 22): s + (1 - s) 4 / 20.
  const double before = search->values().value(Flat(*search, 2, 1));
  EXPECT_NEAR(before, 0.392, 1e-12);
  EXPECT_EQ(search->OnRegionAnswer(region, "maybe").code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NEAR(search->values().value(Flat(*search, 2, 1)), before, 1e-15);  // unchanged
  ASSERT_TRUE(search->OnRegionAnswer(region, "Score: 4").ok());
  EXPECT_NEAR(search->values().value(Flat(*search, 2, 1)), 0.392 + 0.608 * 0.2, 1e-12);
}

// Overlapping views name the same passage frame after frame: by default a code counts once
// (0.05 -> 0.24, and 0.24 again), still a record of the region map; the seed's eq. 20 on every
// answer gives 0.392 (the test above).
TEST(GatewayEroiSearchTest, ACodeNamedAgainAddsNoEvidenceByHand) {
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("red mug", Config());
  ASSERT_TRUE(search.ok());
  search->OnVlmAnswer("Code: C2A, Description: road leading on");
  EXPECT_EQ(search->OnVlmAnswer("code: c2a, description: road leading on").codes_used, 1);
  EXPECT_NEAR(search->values().value(Flat(*search, 2, 1)), 0.24, 1e-12);
  const EroiEvidence third = search->OnVlmAnswer("Code: D1A, Description: sink");
  EXPECT_EQ(third.due.size(), 1u);  // three records of the unit, as before
  // D1A's first time: (3, 0) at the grid's edge has m = 4, (1 - 1/4) 0.05 + 1/4 = 0.2875.
  EXPECT_NEAR(search->values().value(Flat(*search, 3, 0)), 0.2875, 1e-12);
}

TEST(GatewayEroiSearchTest, ATargetNamedByTwoAnswersWithinTwoEdgesIsASightingOnce) {
  EroiSearchConfig two = Config();
  two.sighting_namings = 2;
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("car", two);
  ASSERT_TRUE(search.ok()) << search.status();
  EXPECT_EQ(search->OnVlmAnswer("Code: C2A, Description: no car here; road leading on").sightings,
            0);
  // D1A = (3, 0, 0) = (6, 0) m; A4A = (0, 3) = (0, 6) m is 8.5 m from it. One answer naming both
  // corroborates neither.
  EXPECT_EQ(
      search->OnVlmAnswer("Code: D1A, Description: car seen here\nCode: A4A, Description: a car")
          .sightings,
      0);
  // B1A = (2, 0) m, 4 m from D1A (two edges): the second answer corroborates it.
  EXPECT_EQ(search->OnVlmAnswer("Code: B1A, Description: a red car").sightings, 1);
  EXPECT_EQ(search->OnVlmAnswer("Code: B1A, Description: the car again").sightings, 0);
  EXPECT_EQ(search->OnVlmAnswer("Code: A1A, Description: no car; a road").sightings, 0);
  EXPECT_EQ(search->OnVlmAnswer("Code: Z9Z, Description: car off the grid").sightings, 0);
  ASSERT_EQ(search->sightings().size(), 1u);
  EXPECT_EQ(search->sightings()[0], Eigen::Vector3d(2, 0, 0));
  EXPECT_DOUBLE_EQ(search->inspect_distance_m(), 3.0);
  // One naming suffices by default (sighting_namings 1).
  absl::StatusOr<EroiSearch> eager = EroiSearch::Create("car", Config());
  ASSERT_TRUE(eager.ok()) << eager.status();
  EXPECT_EQ(eager->OnVlmAnswer("Code: D1A, Description: car seen here").sightings, 1);
  EroiSearchConfig bad = Config();
  bad.inspect_distance_m = std::nan("");
  EXPECT_FALSE(EroiSearch::Create("car", bad).ok());
  bad = Config();
  bad.sighting_namings = 0;
  EXPECT_FALSE(EroiSearch::Create("car", bad).ok());
}

// Clues the robot reached while the search went on have failed; after failed_clues_to_geometric
// of them the values stop steering (ApexNav's switch to geometric exploration).
TEST(GatewayEroiSearchTest, CluesTheRobotReachedWithoutTheTargetTurnTheSearchGeometric) {
  EroiSearchConfig config = Config();
  config.failed_clues_to_geometric = 2;
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("car", config);
  ASSERT_TRUE(search.ok()) << search.status();
  // A1A = (0, 0) m, C2A = (4, 2) m, E4A = (8, 6) m: three clues.
  search->OnVlmAnswer("Code: A1A, Description: no car here; road leading on");
  search->OnVlmAnswer("Code: C2A, Description: no car here; gate\nCode: E4A, Description: car");
  search->OnVlmAnswer("Code: C2A, Description: the gate again");  // one clue, not two
  const std::vector<double> steered = search->PlanarValues();
  EXPECT_NEAR(steered[1 * 5 + 2], 0.24, 1e-12);  // C2A's column, as in the first test
  // A clue is reached within r + inspect_distance_m = 2 + 3 m (x-y; the height is the UAV's).
  search->OnRobotAt({-4.0, 6.0, 5.0});  // 7.2 m from A1A, 8.9 m from C2A
  EXPECT_EQ(search->failed_clues(), 0);
  search->OnRobotAt({-3.0, -3.0, 5.0});  // 4.2 m from A1A, 8.6 m from C2A
  EXPECT_EQ(search->failed_clues(), 1);
  EXPECT_FALSE(search->geometric());
  EXPECT_EQ(search->PlanarValues(), steered);
  search->OnRobotAt({-3.0, -3.0, 5.0});  // A1A again: a clue fails once
  EXPECT_EQ(search->failed_clues(), 1);
  search->OnRobotAt({4.0, 2.0, 0.0});  // C2A; E4A is 5.7 m away
  EXPECT_EQ(search->failed_clues(), 2);
  EXPECT_TRUE(search->geometric());
  EXPECT_EQ(search->PlanarValues(), std::vector<double>(20, 0.05));
  // The sighting is still there to be looked at.
  ASSERT_EQ(search->sightings().size(), 1u);
  EXPECT_EQ(search->sightings()[0], Eigen::Vector3d(8, 6, 0));

  // 0 keeps the seed's search: reached clues never turn it.
  config.failed_clues_to_geometric = 0;
  absl::StatusOr<EroiSearch> seed = EroiSearch::Create("car", config);
  ASSERT_TRUE(seed.ok());
  seed->OnVlmAnswer("Code: A1A, Description: no car here; road leading on");
  seed->OnRobotAt({0.0, 0.0, 0.0});
  EXPECT_EQ(seed->failed_clues(), 1);
  EXPECT_FALSE(seed->geometric());
  // A1A in the corner: N_r holds it and its 2 side neighbours, (1 - 1/3) 0.05 + 1/3.
  EXPECT_NEAR(seed->PlanarValues()[0], 0.05 * 2.0 / 3.0 + 1.0 / 3.0, 1e-12);
  config.failed_clues_to_geometric = -1;
  EXPECT_EQ(EroiSearch::Create("car", config).status().code(), absl::StatusCode::kInvalidArgument);
}

TEST(GatewayEroiSearchTest, PlanarValuesAndWindowMatchPlanningsRowMajorEroiGrid) {
  EroiSearchConfig config = Config();
  config.grid.nz = 1;  // two layers: a column's value is the better of the two
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("red mug", config);
  ASSERT_TRUE(search.ok());
  search->OnVlmAnswer("Code: A1B, Description: up high");  // (0, 0, 1) = (0, 0, 2)
  const std::vector<double> planar = search->PlanarValues();
  ASSERT_EQ(planar.size(), 20u);
  // N = 40, prior 0.025; N_r of (0, 0, 2) with r = 2: itself, (2, 0, 2), (0, 2, 2), (0, 0, 0): m
  // = 4.
  EXPECT_NEAR(planar[0], 0.75 * 0.025 + 0.25, 1e-12);  // column (0, 0): max of both layers
  EXPECT_NEAR(planar[1], 0.75 * 0.025 + 0.25, 1e-12);  // x fastest: (1, 0)
  EXPECT_NEAR(planar[5], 0.75 * 0.025 + 0.25, 1e-12);  // (0, 1)
  EXPECT_NEAR(planar[6], 0.025, 1e-12);
  EXPECT_TRUE(search->WindowMin().isApprox(Eigen::Vector2d(-1, -1)));
  EXPECT_TRUE(search->WindowMax().isApprox(Eigen::Vector2d(9, 7)));
}

TEST(GatewayEroiSearchTest, AnnotateDrawsDecodableCodesAndThePromptNamesTheTarget) {
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("red mug", Config());
  ASSERT_TRUE(search.ok());
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(200, 200, 200));
  const cv::Mat blank = image.clone();
  // Camera 4 m before the grid looking along +x: centres 4..10 m ahead are inside the 3-12 m
  // window.
  const EroiObservation observation =
      search->Annotate(Eigen::Vector3d(-4, 3, 0), Eigen::Quaterniond::Identity(),
                       PinholeCamera{320, 320, 320, 240, 640, 480}, image);
  ASSERT_FALSE(observation.labels.empty());
  for (const CodeLabel& label : observation.labels) {
    ASSERT_TRUE(search->grid().Decode(label.code).ok()) << label.code;
    EXPECT_GT(label.distance_m, 3.0);
    EXPECT_LT(label.distance_m, 12.0);
  }
  EXPECT_GT(cv::norm(image, blank, cv::NORM_L1), 0.0);  // codes drawn
  EXPECT_NE(observation.prompt.find("[red mug]"), std::string::npos);
  EXPECT_EQ(EroiSearch::Create("", Config()).status().code(), absl::StatusCode::kInvalidArgument);
}

// Call economy: codes printed into a frame the VLM was asked about are no longer new; turning
// away shows new ones, turning back shows none.
TEST(GatewayEroiSearchTest, CodesOfAskedFramesAreNoLongerNew) {
  EroiSearchConfig config = Config();
  config.grid.min = Eigen::Vector3d(-20, -20, 0);  // 21 x 21 EROIs round the camera
  config.grid.nx = 20;
  config.grid.ny = 20;
  absl::StatusOr<EroiSearch> search = EroiSearch::Create("red mug", config);
  ASSERT_TRUE(search.ok());
  const PinholeCamera camera{320, 320, 320, 240, 640, 480};
  const auto look = [&](double yaw) {
    cv::Mat image(480, 640, CV_8UC3, cv::Scalar(200, 200, 200));
    return search->Annotate(Eigen::Vector3d(0, 0, 1.5),
                            Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())),
                            camera, image);
  };
  const EroiObservation east = look(0.0);
  ASSERT_FALSE(east.labels.empty());
  EXPECT_EQ(search->NewCodes(east), static_cast<int>(east.labels.size()));
  search->OnAsked(east);
  EXPECT_EQ(search->NewCodes(east), 0);
  EXPECT_EQ(search->NewCodes(look(0.0)), 0);  // the same view again
  const EroiObservation west = look(M_PI);    // the codes behind: all new
  ASSERT_FALSE(west.labels.empty());
  EXPECT_EQ(search->NewCodes(west), static_cast<int>(west.labels.size()));
}

}  // namespace
}  // namespace semnav::reasoning
