#include "services/relocalization/server/proto_convert.h"

#include <unordered_set>

#include "absl/strings/str_cat.h"
#include "semnav/common/v1/errors.pb.h"
#include "services/common/status/field_error.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/value_checks.h"

namespace semnav::relocalization {

absl::StatusOr<Landmark> LandmarkFromProto(const v1::Landmark& proto, size_t descriptor_dim,
                                           absl::string_view field) {
  if (!proto.has_position()) {
    return FieldError(absl::StatusCode::kInvalidArgument, absl::StrCat(field, ".position"),
                      "is required");
  }
  Landmark l;
  l.id = proto.id();
  l.position = {proto.position().x(), proto.position().y(), proto.position().z()};
  l.scale = proto.scale_m();
  l.descriptor.assign(proto.embedding().begin(), proto.embedding().end());
  l.observations = proto.observations() == 0 ? 1 : proto.observations();
  if (absl::Status s = ValidateLandmark(l, descriptor_dim, field); !s.ok()) return s;
  return l;
}

absl::StatusOr<std::vector<Landmark>> LandmarksFromProto(
    const google::protobuf::RepeatedPtrField<v1::Landmark>& protos, size_t descriptor_dim,
    absl::string_view field) {
  // Before converting anything: a huge list is rejected without copying it.
  if (auto s = CheckCount(static_cast<size_t>(protos.size()), field, kMaxLandmarksPerRequest);
      !s.ok()) {
    return s;
  }
  std::vector<Landmark> out;
  out.reserve(static_cast<size_t>(protos.size()));
  for (int i = 0; i < protos.size(); ++i) {
    // Without a map yet, the first landmark fixes the length for the rest.
    const size_t dim =
        descriptor_dim != 0 || out.empty() ? descriptor_dim : out.front().descriptor.size();
    absl::StatusOr<Landmark> l =
        LandmarkFromProto(protos[i], dim, absl::StrCat(field, "[", i, "]"));
    if (!l.ok()) return l.status();
    out.push_back(*std::move(l));
  }
  return out;
}

void LandmarkToProto(const Landmark& landmark, v1::Landmark* proto) {
  proto->set_id(landmark.id);
  proto->mutable_position()->set_x(landmark.position.x());
  proto->mutable_position()->set_y(landmark.position.y());
  proto->mutable_position()->set_z(landmark.position.z());
  proto->set_scale_m(landmark.scale);
  proto->mutable_embedding()->Assign(landmark.descriptor.begin(), landmark.descriptor.end());
  proto->set_observations(landmark.observations);
}

HeadTensors HeadTensorsFromProto(const v1::HeadTensors& proto) {
  HeadTensors h;
  h.width = proto.width();
  h.height = proto.height();
  h.heatmap_channels = proto.heatmap_channels();
  h.heatmap.assign(proto.heatmap().begin(), proto.heatmap().end());
  h.offset.assign(proto.offset().begin(), proto.offset().end());
  h.size.assign(proto.box_size().begin(), proto.box_size().end());
  h.feature_channels = proto.feature_channels();
  h.features.assign(proto.features().begin(), proto.features().end());
  h.stride_x = proto.stride_x();
  h.stride_y = proto.stride_y();
  return h;
}

void ObjectPointToProto(const ObjectPoint& point, v1::ObjectPoint* proto) {
  proto->set_u(point.u);
  proto->set_v(point.v);
  proto->set_score(point.score);
  proto->mutable_box()->set_x_min(point.box.x0);
  proto->mutable_box()->set_y_min(point.box.y0);
  proto->mutable_box()->set_x_max(point.box.x1);
  proto->mutable_box()->set_y_max(point.box.y1);
  proto->mutable_embedding()->Assign(point.descriptor.begin(), point.descriptor.end());
  proto->set_label(DescriptorLabel(point.descriptor));
}

void PoseToProto(const Eigen::Isometry3d& pose, common::v1::Pose* proto) {
  const Eigen::Quaterniond q(pose.linear());
  proto->mutable_position()->set_x(pose.translation().x());
  proto->mutable_position()->set_y(pose.translation().y());
  proto->mutable_position()->set_z(pose.translation().z());
  proto->mutable_orientation()->set_w(q.w());
  proto->mutable_orientation()->set_x(q.x());
  proto->mutable_orientation()->set_y(q.y());
  proto->mutable_orientation()->set_z(q.z());
}

void SolutionToProto(const RelocalizationResult& result, const std::vector<uint64_t>& query_ids,
                     const std::vector<uint64_t>& map_ids, v1::PoseSolution* proto) {
  PoseToProto(result.map_from_query, proto->mutable_map_from_query());
  PoseToProto(result.initial_map_from_query, proto->mutable_initial_map_from_query());
  const std::unordered_set<size_t> inliers(result.inliers.begin(), result.inliers.end());
  for (size_t i = 0; i < result.matches.size(); ++i) {
    const Match& m = result.matches[i];
    v1::LandmarkMatch* out = proto->add_matches();
    out->set_query_index(static_cast<uint32_t>(m.query));
    if (!query_ids.empty()) out->set_query_landmark_id(query_ids[m.query]);
    out->set_map_landmark_id(map_ids[m.map]);
    out->set_similarity(m.similarity);
    out->set_inlier(inliers.contains(i));
  }
  proto->set_inlier_count(static_cast<uint32_t>(result.inliers.size()));
  proto->set_rms_residual_m(result.rms_residual_m);
  proto->set_reliable(result.reliable);
}

absl::Status WithErrorInfo(const absl::Status& status, absl::string_view reason) {
  // Core names its fields (InvalidField / FieldStatus); ToGrpcStatus turns the payloads into
  // ErrorInfo{reason, field}. Errors core gave no reason get the step's.
  return WithDefaultReason(status, reason);
}

}  // namespace semnav::relocalization
