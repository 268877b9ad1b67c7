#include "services/relocalization/core/object_points.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "services/common/status/field_error.h"

namespace semnav::relocalization {
namespace {

using ::testing::HasSubstr;

double Sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x)); }

// 5 x 4 grid, two heatmap channels, stride 4. Channel sums: 3 at (1,1), 2.5 at (2,1),
// 1 at (4,3), -5 elsewhere.
HeadTensors HandMadeHeads() {
  HeadTensors h;
  h.width = 5;
  h.height = 4;
  h.heatmap_channels = 2;
  h.stride_x = h.stride_y = 4.0;
  const size_t cells = 20;
  h.heatmap.assign(2 * cells, 0.0f);
  for (size_t i = 0; i < cells; ++i) h.heatmap[i] = -5.0f;
  auto at = [](int x, int y) { return static_cast<size_t>(y * 5 + x); };
  h.heatmap[at(1, 1)] = 2.0f;
  h.heatmap[cells + at(1, 1)] = 1.0f;
  h.heatmap[at(2, 1)] = 2.5f;
  h.heatmap[at(4, 3)] = 1.0f;
  h.offset.assign(2 * cells, 0.0f);
  h.offset[at(1, 1)] = 0.25f;
  h.offset[cells + at(1, 1)] = -0.5f;
  h.size.assign(2 * cells, 1.0f);
  for (size_t c : {at(1, 1), at(2, 1)}) {
    h.size[c] = 2.0f;
    h.size[cells + c] = 4.0f;
  }
  return h;
}

TEST(RelocObjectPointsTest, MaxPoolSuppressesNeighbourAndTopKDropsFlatBackground) {
  ObjectPointParams params;
  params.nms_kernel = 1;
  params.top_k = 2;
  const auto points = ExtractObjectPoints(HandMadeHeads(), params);
  ASSERT_TRUE(points.ok()) << points.status();
  ASSERT_EQ(points->size(), 2u);
  const ObjectPoint& first = (*points)[0];
  EXPECT_NEAR(first.score, Sigmoid(3.0), 1e-9);
  EXPECT_DOUBLE_EQ(first.u, 5.0);  // (1 + 0.25) * 4
  EXPECT_DOUBLE_EQ(first.v, 2.0);  // (1 - 0.5) * 4
  EXPECT_DOUBLE_EQ(first.box.x0, 1.0);
  EXPECT_DOUBLE_EQ(first.box.y0, -6.0);
  EXPECT_DOUBLE_EQ(first.box.x1, 9.0);
  EXPECT_DOUBLE_EQ(first.box.y1, 10.0);
  ASSERT_EQ(first.descriptor.size(), 2u);  // per-channel sigmoid without a feature head
  EXPECT_NEAR(first.descriptor[0], Sigmoid(2.0), 1e-6);
  EXPECT_NEAR(first.descriptor[1], Sigmoid(1.0), 1e-6);
  EXPECT_NEAR((*points)[1].score, Sigmoid(1.0), 1e-9);  // (4,3); (2,1) was pooled away
  EXPECT_DOUBLE_EQ((*points)[1].u, 16.0);
  EXPECT_DOUBLE_EQ((*points)[1].v, 12.0);
}

TEST(RelocObjectPointsTest, KernelZeroKeepsNeighbourUnlessBoxesOverlap) {
  ObjectPointParams params;
  params.nms_kernel = 0;
  params.top_k = 2;
  auto points = ExtractObjectPoints(HandMadeHeads(), params);
  ASSERT_TRUE(points.ok());
  ASSERT_EQ(points->size(), 2u);
  EXPECT_NEAR((*points)[1].score, Sigmoid(2.5), 1e-9);
  // Boxes (1,-6,9,10) and (4,-4,12,12): IoU = 70 / 186 = 0.376.
  EXPECT_NEAR(BoxIou((*points)[0].box, (*points)[1].box), 70.0 / 186.0, 1e-12);
  params.box_iou_threshold = 0.3;
  points = ExtractObjectPoints(HandMadeHeads(), params);
  ASSERT_TRUE(points.ok());
  EXPECT_EQ(points->size(), 1u);
}

TEST(RelocObjectPointsTest, DescriptorComesFromFeatureHead) {
  HeadTensors h = HandMadeHeads();
  h.feature_channels = 3;
  h.features.assign(3 * 20, 0.0f);
  h.features[6] = 0.5f;        // channel 0 at (1,1)
  h.features[20 + 6] = -1.0f;  // channel 1
  h.features[40 + 6] = 2.0f;   // channel 2
  ObjectPointParams params;
  params.top_k = 1;
  const auto points = ExtractObjectPoints(h, params);
  ASSERT_TRUE(points.ok());
  ASSERT_EQ(points->size(), 1u);
  EXPECT_EQ((*points)[0].descriptor, (Descriptor{0.5f, -1.0f, 2.0f}));
  EXPECT_EQ(DescriptorLabel((*points)[0].descriptor), 2);
}

TEST(RelocObjectPointsTest, MalformedTensorsNameTheTensor) {
  HeadTensors h = HandMadeHeads();
  h.heatmap.pop_back();
  auto r = ExtractObjectPoints(h, {});
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(r.status().message(), HasSubstr("tensors.heatmap"));

  h = HandMadeHeads();
  h.offset[3] = std::numeric_limits<float>::quiet_NaN();
  r = ExtractObjectPoints(h, {});
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(r.status().message(), HasSubstr("tensors.offset"));

  h = HandMadeHeads();
  h.heatmap_channels = 1 << 20;  // absurd sizes are refused before any arithmetic
  r = ExtractObjectPoints(h, {});
  EXPECT_THAT(r.status().message(), HasSubstr("tensors.heatmap_channels"));

  h = HandMadeHeads();
  h.feature_channels = 2;  // declared but missing
  r = ExtractObjectPoints(h, {});
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(r.status().message(), HasSubstr("tensors.features"));
}

TEST(RelocObjectPointsTest, SizesAndStridesNameTheirOwnField) {
  HeadTensors h = HandMadeHeads();
  h.width = 0;
  auto r = ExtractObjectPoints(h, {});
  EXPECT_EQ(ErrorField(r.status()).value_or(""), "tensors.width");
  h = HandMadeHeads();
  h.height = 1 << 20;
  r = ExtractObjectPoints(h, {});
  EXPECT_EQ(ErrorField(r.status()).value_or(""), "tensors.height");
  h = HandMadeHeads();
  h.stride_y = 1e300;  // finite, but every box would leave any image
  r = ExtractObjectPoints(h, {});
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(r.status()).value_or(""), "tensors.stride_y");
  h = HandMadeHeads();
  h.size.pop_back();  // the wire name of the size head is box_size
  r = ExtractObjectPoints(h, {});
  EXPECT_EQ(ErrorField(r.status()).value_or(""), "tensors.box_size");
}

}  // namespace
}  // namespace semnav::relocalization
