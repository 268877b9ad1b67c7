#include "services/mapping/server/proto_convert.h"

#include <gtest/gtest.h>

#include "services/common/status/grpc_status.h"

namespace semnav::mapping {
namespace {

v1::SensorFrame TinyFrame() {
  v1::SensorFrame frame;
  frame.mutable_header()->set_robot_id("r1");
  frame.mutable_header()->mutable_stamp()->set_seconds(2);
  frame.mutable_header()->mutable_stamp()->set_nanos(5);
  auto* k = frame.mutable_intrinsics();
  k->set_width(2);
  k->set_height(1);
  k->set_fx(100);
  k->set_fy(100);
  frame.mutable_depth()->set_width(2);
  frame.mutable_depth()->set_height(1);
  frame.mutable_depth()->set_encoding(semnav::common::v1::IMAGE_ENCODING_DEPTH_16UC1_MM);
  frame.mutable_depth()->set_data(std::string(4, '\0'));
  frame.mutable_camera_pose()->mutable_orientation()->set_w(1.0);
  return frame;
}

TEST(ProtoConvertTest, FrameFieldsArrive) {
  const absl::StatusOr<SensorFrame> frame = FrameFromProto(TinyFrame());
  ASSERT_TRUE(frame.ok());
  EXPECT_EQ(frame->stamp_ns, 2'000'000'005);
  EXPECT_EQ(frame->depth.encoding, DepthEncoding::kMillimetres16U);
  EXPECT_EQ(frame->intrinsics.width, 2);
  EXPECT_EQ(frame->pose.orientation.w(), 1.0);
}

TEST(ProtoConvertTest, RejectsWrongRgbEncodingAndMaskSize) {
  v1::SensorFrame proto = TinyFrame();
  proto.mutable_rgb()->set_encoding(semnav::common::v1::IMAGE_ENCODING_RGB8);
  EXPECT_EQ(FrameFromProto(proto).status().message().substr(0, 13), "rgb.encoding:");
  proto = TinyFrame();
  auto* mask = proto.add_detections()->mutable_mask();
  mask->set_encoding(semnav::common::v1::IMAGE_ENCODING_MONO8);
  mask->set_width(2);
  mask->set_height(1);
  mask->set_data("x");
  EXPECT_EQ(FrameFromProto(proto).status().message().substr(0, 19), "detections[0].mask:");
}

TEST(ProtoConvertTest, ConversionErrorsNameTheirFieldInErrorInfo) {
  v1::SensorFrame proto = TinyFrame();
  proto.mutable_rgb()->set_encoding(semnav::common::v1::IMAGE_ENCODING_RGB8);
  const grpc::Status wire = ToGrpcStatus(FrameFromProto(proto).status());
  const std::optional<semnav::common::v1::ErrorInfo> info =
      GetDetail<semnav::common::v1::ErrorInfo>(wire);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->field(), "rgb.encoding");
  EXPECT_EQ(info->reason(), "FIELD_INVALID");
}

}  // namespace
}  // namespace semnav::mapping
