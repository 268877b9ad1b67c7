#include "services/mapping/core/octomap_integrator.h"

#include <gtest/gtest.h>

#include "services/mapping/core/depth_projection.h"
#include "services/mapping/core/frame_validation.h"
#include "services/mapping/core/octree_agreement.h"
#include "services/mapping/core/octree_batch_update.h"
#include "services/mapping/testing/synthetic_room.h"

namespace semnav::mapping {
namespace {

octomap::Pointcloud ToPointcloud(const std::vector<Eigen::Vector3f>& points) {
  octomap::Pointcloud cloud;
  for (const Eigen::Vector3f& p : points) cloud.push_back(p.x(), p.y(), p.z());
  return cloud;
}

TEST(OctomapIntegratorTest, SingleRayMarksEndpointOccupiedAndPathFree) {
  octomap::OcTree tree(0.1);
  const OctomapIntegrator integrator(2);
  const std::vector<TouchedVoxel> touched = integrator.Integrate(
      tree, {Eigen::Vector3f(1.05f, 0.05f, 0.05f)}, Eigen::Vector3f(0.05f, 0.05f, 0.05f));
  // Voxels x = 0.05 .. 0.95 are passed (10), the voxel at 1.05 is hit.
  ASSERT_EQ(touched.size(), 11u);
  EXPECT_TRUE(tree.isNodeOccupied(tree.search(1.05, 0.05, 0.05)));
  EXPECT_FALSE(tree.isNodeOccupied(tree.search(0.55, 0.05, 0.05)));
  EXPECT_FALSE(tree.isNodeOccupied(tree.search(0.05, 0.05, 0.05)));
  EXPECT_EQ(tree.search(1.15, 0.05, 0.05), nullptr);
  int occupied = 0;
  for (const TouchedVoxel& v : touched) occupied += v.occupied ? 1 : 0;
  EXPECT_EQ(occupied, 1);
}

TEST(OctomapIntegratorTest, CastingOnAnEmptyKeySpaceTreeThenApplyingEqualsIntegrate) {
  // The mapping engine casts rays outside its lock with an empty tree of the same resolution.
  const std::vector<Eigen::Vector3f> points = {
      {1.05f, 0.05f, 0.05f}, {0.45f, 0.95f, -0.25f}, {-0.75f, -0.35f, 0.55f}};
  const Eigen::Vector3f origin(0.05f, 0.05f, 0.05f);
  const OctomapIntegrator integrator(2);
  octomap::OcTree integrated(0.1);
  octomap::OcTree applied(0.1);
  for (int scan = 0; scan < 3; ++scan) {  // later scans update voxels already in the tree
    const std::vector<TouchedVoxel> expected = integrator.Integrate(integrated, points, origin);
    const octomap::OcTree key_space(0.1);
    const std::vector<TouchedVoxel> touched =
        ApplyVoxelUpdates(applied, integrator.CastScan(key_space, points, origin));
    ASSERT_EQ(touched.size(), expected.size());
    for (size_t i = 0; i < touched.size(); ++i) {
      EXPECT_EQ(touched[i].key, expected[i].key);
      EXPECT_EQ(touched[i].occupied, expected[i].occupied);
    }
  }
  ASSERT_EQ(applied.size(), integrated.size());
  for (auto it = integrated.begin_leafs(); it != integrated.end_leafs(); ++it) {
    const octomap::OcTreeNode* node = applied.search(it.getKey(), it.getDepth());
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(node->getLogOdds(), it->getLogOdds());
  }
}

TEST(OctomapIntegratorTest, AgreesWithPlainInsertPointCloudOnRoomSequence) {
  const testing::SyntheticRoom room = testing::StandardRoom();
  const DepthRange range;
  octomap::OcTree reference(0.05);
  octomap::OcTree fast(0.05);
  const OctomapIntegrator integrator(2);
  for (const CameraPose& pose : testing::RoomTour(room, 4)) {
    const SensorFrame frame = testing::RenderFrame(room, pose, 0);
    const cv::Mat depth = DecodeDepth(frame.depth);
    const Eigen::Vector3f origin = pose.position.cast<float>();
    const std::vector<Eigen::Vector3f> all = ProjectDepth(depth, frame.intrinsics, pose, range, 1);
    reference.insertPointCloud(ToPointcloud(all),
                               octomap::point3d(origin.x(), origin.y(), origin.z()), range.max_m);
    integrator.Integrate(fast, all, origin);
  }
  const OctreeAgreement agreement = CompareOctrees(reference, fast);
  EXPECT_GE(agreement.occupied, 0.98);
  EXPECT_GE(agreement.free, 0.95);
}

}  // namespace
}  // namespace semnav::mapping
