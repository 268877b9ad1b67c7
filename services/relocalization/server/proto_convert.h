#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "semnav/relocalization/v1/relocalization.pb.h"
#include "services/relocalization/core/landmark.h"
#include "services/relocalization/core/object_points.h"
#include "services/relocalization/core/relocalizer.h"

namespace semnav::relocalization {

// Request landmark -> core landmark, validated (finite position, scale > 0, descriptor of
// `descriptor_dim` entries, 0 = any). Errors carry an ErrorInfo naming `field`.
absl::StatusOr<Landmark> LandmarkFromProto(const v1::Landmark& proto, size_t descriptor_dim,
                                           absl::string_view field);
absl::StatusOr<std::vector<Landmark>> LandmarksFromProto(
    const google::protobuf::RepeatedPtrField<v1::Landmark>& protos, size_t descriptor_dim,
    absl::string_view field);
void LandmarkToProto(const Landmark& landmark, v1::Landmark* proto);

// Shape checks happen in ExtractObjectPoints (its errors name "tensors.<head>").
HeadTensors HeadTensorsFromProto(const v1::HeadTensors& proto);
void ObjectPointToProto(const ObjectPoint& point, v1::ObjectPoint* proto);

// Pose/matches of a relocalization; `query_ids` (may be empty) and `map_ids` turn core
// indexes into landmark ids.
void SolutionToProto(const RelocalizationResult& result, const std::vector<uint64_t>& query_ids,
                     const std::vector<uint64_t>& map_ids, v1::PoseSolution* proto);
void PoseToProto(const Eigen::Isometry3d& pose, common::v1::Pose* proto);

// A core error with `reason` as its ErrorInfo.reason unless core chose one (field errors keep
// their field and reason).
absl::Status WithErrorInfo(const absl::Status& status, absl::string_view reason);

}  // namespace semnav::relocalization
