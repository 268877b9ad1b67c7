#include "services/relocalization/server/proto_convert.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "semnav/common/v1/errors.pb.h"
#include "services/common/status/field_error.h"
#include "services/common/status/grpc_status.h"

namespace semnav::relocalization {
namespace {

v1::Landmark Valid() {
  v1::Landmark l;
  l.mutable_position()->set_x(1.0);
  l.set_scale_m(0.5);
  l.add_embedding(0.2f);
  l.add_embedding(0.8f);
  return l;
}

// The field the client will see: what ToGrpcStatus puts into ErrorInfo.
std::string FieldOf(const absl::Status& s) {
  const auto info = GetDetail<common::v1::ErrorInfo>(FromGrpcStatus(ToGrpcStatus(s)));
  return info ? info->field() : "";
}

TEST(RelocProtoConvertTest, LandmarkRoundTrip) {
  const auto l = LandmarkFromProto(Valid(), 2, "observed[0]");
  ASSERT_TRUE(l.ok()) << l.status();
  EXPECT_EQ(l->observations, 1u);  // 0 on the wire reads as 1
  v1::Landmark back;
  LandmarkToProto(*l, &back);
  EXPECT_EQ(back.position().x(), 1.0);
  EXPECT_EQ(back.embedding_size(), 2);
  EXPECT_EQ(back.observations(), 1u);
}

TEST(RelocProtoConvertTest, ErrorsCarryTheRequestFieldPath) {
  v1::Landmark l = Valid();
  l.clear_position();
  EXPECT_EQ(FieldOf(LandmarkFromProto(l, 2, "landmarks[3]").status()), "landmarks[3].position");
  l = Valid();
  l.set_scale_m(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(FieldOf(LandmarkFromProto(l, 2, "landmarks[3]").status()), "landmarks[3].scale_m");

  google::protobuf::RepeatedPtrField<v1::Landmark> list;
  *list.Add() = Valid();
  *list.Add() = Valid();
  list.Mutable(1)->add_embedding(0.1f);  // length differs from the first one's
  const auto all = LandmarksFromProto(list, 0, "landmarks");
  EXPECT_EQ(all.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(FieldOf(all.status()), "landmarks[1].embedding");
}

TEST(RelocProtoConvertTest, WithErrorInfoKeepsTheFieldCoreNamedAndNeverParsesMessages) {
  const absl::Status named =
      WithErrorInfo(InvalidField("tensors.offset", "must be finite"), "DETECTOR_FAILED");
  EXPECT_EQ(FieldOf(named), "tensors.offset");
  EXPECT_EQ(named.message(), "tensors.offset: must be finite");
  EXPECT_EQ(GetDetail<common::v1::ErrorInfo>(FromGrpcStatus(ToGrpcStatus(named)))->reason(),
            "FIELD_INVALID");
  const absl::Status reason_only =
      WithErrorInfo(absl::NotFoundError("no_field: 2 of 9 pairs agree"), "RELOCALIZATION_FAILED");
  EXPECT_EQ(FieldOf(reason_only), "");
  const auto info = GetDetail<common::v1::ErrorInfo>(FromGrpcStatus(ToGrpcStatus(reason_only)));
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->reason(), "RELOCALIZATION_FAILED");
}

TEST(RelocProtoConvertTest, PoseToProtoWritesAUnitQuaternion) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(1, 2, 3);
  common::v1::Pose out;
  PoseToProto(pose, &out);
  EXPECT_NEAR(out.orientation().w(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(out.orientation().z(), std::sqrt(0.5), 1e-12);
  EXPECT_EQ(out.position().z(), 3.0);
}

}  // namespace
}  // namespace semnav::relocalization
