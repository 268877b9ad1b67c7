#include "services/relocalization/core/onnx_heads.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace semnav::relocalization {
namespace {

using ::testing::HasSubstr;

// Builds the tiny model with python3-onnx; empty when python3-onnx is unavailable.
std::string BuildTinyModel() {
  const std::string python = SEMNAV_RELOC_PYTHON3;
  if (python.empty() || std::system((python + " -c 'import onnx' 2>/dev/null").c_str()) != 0) {
    return "";
  }
  const std::string out = ::testing::TempDir() + "/tiny_centernet.onnx";
  const std::string cmd = python + " " SEMNAV_RELOC_TESTDATA "/make_centernet_onnx.py " + out;
  return std::system(cmd.c_str()) == 0 ? out : "";
}

OnnxHeadsConfig TinyConfig(const std::string& path) {
  OnnxHeadsConfig c;
  c.model_path = path;
  c.input_width = 8;
  c.input_height = 8;
  c.feature_output = "features";
  return c;
}

// 16 x 16 BGR image: G = 128 everywhere, R = 255 on the 2x2 block of grid cell (5, 2).
cv::Mat TestImage() {
  cv::Mat image(16, 16, CV_8UC3, cv::Scalar(0, 128, 0));
  image(cv::Rect(10, 4, 2, 2)).setTo(cv::Scalar(0, 128, 255));
  return image;
}

TEST(RelocOnnxHeadsTest, ReadsEveryHeadOfATinyCenterNetGraph) {
  const std::string model = BuildTinyModel();
  if (model.empty()) GTEST_SKIP() << "python3-onnx is not installed (apt install python3-onnx)";
  auto heads = OnnxHeads::Load(TinyConfig(model));
  ASSERT_TRUE(heads.ok()) << heads.status();
  const auto t = (*heads)->Run(TestImage());
  ASSERT_TRUE(t.ok()) << t.status();
  ASSERT_EQ(t->width, 8);
  ASSERT_EQ(t->height, 8);
  EXPECT_EQ(t->heatmap_channels, 2);
  EXPECT_EQ(t->feature_channels, 4);
  EXPECT_DOUBLE_EQ(t->stride_x, 2.0);
  EXPECT_DOUBLE_EQ(t->stride_y, 2.0);
  const size_t peak = 2 * 8 + 5, cells = 64;
  EXPECT_NEAR(t->heatmap[peak], 2.0, 1e-5);          // 4R - 2 with R = 1
  EXPECT_NEAR(t->heatmap[cells + peak], 1.0, 1e-5);  // 2R - 1
  EXPECT_NEAR(t->heatmap[0], -2.0, 1e-5);
  EXPECT_NEAR(t->size[peak], 4.0, 1e-5);

  ObjectPointParams params;
  params.top_k = 1;
  const auto points = ExtractObjectPoints(*t, params);
  ASSERT_TRUE(points.ok()) << points.status();
  ASSERT_EQ(points->size(), 1u);
  const ObjectPoint& p = (*points)[0];
  EXPECT_NEAR(p.score, 1.0 / (1.0 + std::exp(-3.0)), 1e-6);
  EXPECT_NEAR(p.u, 10.5, 1e-5);  // (5 + 0.25) * 2
  EXPECT_NEAR(p.v, 3.5, 1e-5);   // (2 - 0.25) * 2
  EXPECT_NEAR(p.box.x1 - p.box.x0, 8.0, 1e-5);
  EXPECT_NEAR(p.box.y1 - p.box.y0, 6.0, 1e-5);
  ASSERT_EQ(p.descriptor.size(), 4u);
  EXPECT_NEAR(p.descriptor[0], 1.0, 1e-5);
  EXPECT_NEAR(p.descriptor[1], 128.0 / 255.0, 1e-5);
  EXPECT_NEAR(p.descriptor[2], 0.0, 1e-5);
  EXPECT_NEAR(p.descriptor[3], 0.5, 1e-5);
}

TEST(RelocOnnxHeadsTest, BadModelAndImageAreNamed) {
  auto missing = OnnxHeads::Load(TinyConfig("/nonexistent/model.onnx"));
  EXPECT_EQ(missing.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(missing.status().message(), HasSubstr("model_path"));

  const std::string garbage = ::testing::TempDir() + "/garbage.onnx";
  {
    std::FILE* f = std::fopen(garbage.c_str(), "w");
    std::fputs("not a model", f);
    std::fclose(f);
  }
  auto bad = OnnxHeads::Load(TinyConfig(garbage));
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);

  const std::string model = BuildTinyModel();
  if (model.empty()) GTEST_SKIP() << "python3-onnx is not installed (apt install python3-onnx)";
  auto heads = OnnxHeads::Load(TinyConfig(model));
  ASSERT_TRUE(heads.ok());
  const auto empty = (*heads)->Run(cv::Mat());
  EXPECT_EQ(empty.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(empty.status().message(), HasSubstr("image"));
}

}  // namespace
}  // namespace semnav::relocalization
