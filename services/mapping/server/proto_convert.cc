#include "services/mapping/server/proto_convert.h"

#include <algorithm>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/grpc_status.h"

namespace semnav::mapping {
namespace {

using semnav::common::v1::GridLayerKind;
using semnav::common::v1::ImageEncoding;

DepthEncoding DepthEncodingOf(ImageEncoding encoding) {
  switch (encoding) {
    case semnav::common::v1::IMAGE_ENCODING_DEPTH_16UC1_MM:
      return DepthEncoding::kMillimetres16U;
    case semnav::common::v1::IMAGE_ENCODING_DEPTH_32FC1_M:
      return DepthEncoding::kMetres32F;
    default:
      return DepthEncoding::kUnknown;
  }
}

Eigen::Vector3d Vec(const semnav::common::v1::Vector3& v) { return {v.x(), v.y(), v.z()}; }

void SetVec(const Eigen::Vector3d& v, semnav::common::v1::Vector3* out) {
  out->set_x(v.x());
  out->set_y(v.y());
  out->set_z(v.z());
}

const std::vector<uint8_t>* LayerBytes(const GridLayers& layers, GridLayerKind kind) {
  switch (kind) {
    case semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL:
      return &layers.hierarchical;
    case semnav::common::v1::GRID_LAYER_KIND_OBSTACLE_PROBABILITY:
      return &layers.obstacle_probability;
    case semnav::common::v1::GRID_LAYER_KIND_EXPLORED:
      return &layers.explored;
    case semnav::common::v1::GRID_LAYER_KIND_SEMANTIC:
      return &layers.semantic;
    case semnav::common::v1::GRID_LAYER_KIND_INFLATED:
      return &layers.inflated;
    case semnav::common::v1::GRID_LAYER_KIND_OCCUPANCY:
      return &layers.occupancy;
    default:
      return nullptr;
  }
}

}  // namespace

// Year 2255: far beyond any robot's clock, and x 1e9 still fits int64 nanoseconds.
constexpr int64_t kMaxStampSeconds = 9'000'000'000;

absl::StatusOr<SensorFrame> FrameFromProto(const v1::SensorFrame& proto) {
  SensorFrame frame;
  frame.robot_id = proto.header().robot_id();
  // Checked before the multiplication, which would overflow int64 (year 2262) otherwise.
  const auto& stamp = proto.header().stamp();
  if (stamp.seconds() < 0 || stamp.seconds() > kMaxStampSeconds) {
    return InvalidField("header.stamp.seconds",
                        absl::StrCat("must be in [0, ", kMaxStampSeconds, "] (Unix seconds)"));
  }
  if (stamp.nanos() < 0 || stamp.nanos() >= 1'000'000'000) {
    return InvalidField("header.stamp.nanos", "must be in [0, 999999999]");
  }
  frame.stamp_ns = stamp.seconds() * 1'000'000'000 + stamp.nanos();
  const auto& k = proto.intrinsics();
  frame.intrinsics = {
      static_cast<int>(k.width()), static_cast<int>(k.height()), k.fx(), k.fy(), k.cx(), k.cy()};
  frame.depth.width = static_cast<int>(proto.depth().width());
  frame.depth.height = static_cast<int>(proto.depth().height());
  frame.depth.encoding = DepthEncodingOf(proto.depth().encoding());
  frame.depth.data = proto.depth().data();
  frame.pose.position = Vec(proto.camera_pose().position());
  const auto& q = proto.camera_pose().orientation();
  frame.pose.orientation = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
  if (proto.has_rgb()) {
    const ImageEncoding e = proto.rgb().encoding();
    if (e != semnav::common::v1::IMAGE_ENCODING_PNG &&
        e != semnav::common::v1::IMAGE_ENCODING_JPEG) {
      return InvalidField("rgb.encoding", "must be IMAGE_ENCODING_PNG or IMAGE_ENCODING_JPEG");
    }
    frame.rgb_encoded = proto.rgb().data();
  }
  for (int i = 0; i < proto.detections_size(); ++i) {
    const v1::Detection& d = proto.detections(i);
    Detection det;
    det.label = d.label();
    det.score = d.score();
    det.box = {d.box().x_min(), d.box().y_min(), d.box().x_max(), d.box().y_max()};
    if (d.has_mask()) {
      const auto& m = d.mask();
      if (m.encoding() != semnav::common::v1::IMAGE_ENCODING_MONO8 || m.width() != k.width() ||
          m.height() != k.height() ||
          m.data().size() != static_cast<size_t>(k.width()) * k.height()) {
        return InvalidField(absl::StrCat("detections[", i, "].mask"),
                            "must be an IMAGE_ENCODING_MONO8 image of the depth image's size");
      }
      det.mask.assign(m.data().begin(), m.data().end());
    }
    det.embedding.assign(d.embedding().begin(), d.embedding().end());
    frame.detections.push_back(std::move(det));
  }
  for (const auto& p : proto.lidar_points()) frame.lidar_points.push_back(Vec(p).cast<float>());
  frame.pose_untrusted = proto.pose_untrusted();
  frame.detector_ran = proto.detector_ran();
  return frame;
}

absl::Status CheckLayerKinds(const google::protobuf::RepeatedField<int>& kinds,
                             absl::string_view field) {
  for (int kind : kinds) {
    if (!semnav::common::v1::GridLayerKind_IsValid(kind) ||
        kind == semnav::common::v1::GRID_LAYER_KIND_UNSPECIFIED) {
      return InvalidField(field, absl::StrCat("unknown or unspecified layer kind ", kind));
    }
  }
  return absl::OkStatus();
}

semnav::common::v1::GridMap GridToProto(const GridLayers& layers, uint64_t revision,
                                        const std::vector<GridLayerKind>& kinds) {
  semnav::common::v1::GridMap grid;
  grid.mutable_header()->set_frame_id("map");
  grid.set_resolution(layers.resolution);
  grid.mutable_origin()->set_x(layers.origin_x);
  grid.mutable_origin()->set_y(layers.origin_y);
  grid.set_width(static_cast<uint32_t>(layers.width));
  grid.set_height(static_cast<uint32_t>(layers.height));
  grid.set_revision(revision);
  grid.set_foot_height(layers.heights.foot_m);
  grid.set_ceiling_height(layers.heights.ceiling_m);
  std::vector<GridLayerKind> wanted = kinds;
  if (wanted.empty()) {
    wanted = {semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL,
              semnav::common::v1::GRID_LAYER_KIND_OCCUPANCY,
              semnav::common::v1::GRID_LAYER_KIND_OBSTACLE_PROBABILITY,
              semnav::common::v1::GRID_LAYER_KIND_EXPLORED,
              semnav::common::v1::GRID_LAYER_KIND_INFLATED,
              semnav::common::v1::GRID_LAYER_KIND_SEMANTIC};
  }
  for (GridLayerKind kind : wanted) {
    const std::vector<uint8_t>* bytes = LayerBytes(layers, kind);
    if (bytes == nullptr) continue;
    auto* layer = grid.add_layers();
    layer->set_kind(kind);
    layer->set_data(std::string(bytes->begin(), bytes->end()));
    if (kind == semnav::common::v1::GRID_LAYER_KIND_SEMANTIC) {
      for (const std::string& label : layers.semantic_labels) grid.add_semantic_labels(label);
    }
  }
  return grid;
}

v1::RelationKind RelationToProto(RelationKind kind) {
  switch (kind) {
    case RelationKind::kNear:
      return v1::RELATION_KIND_NEAR;
    case RelationKind::kLeftOf:
      return v1::RELATION_KIND_LEFT_OF;
    case RelationKind::kRightOf:
      return v1::RELATION_KIND_RIGHT_OF;
    case RelationKind::kInFrontOf:
      return v1::RELATION_KIND_IN_FRONT_OF;
    case RelationKind::kBehind:
      return v1::RELATION_KIND_BEHIND;
    case RelationKind::kOn:
      return v1::RELATION_KIND_ON;
    case RelationKind::kAbove:
      return v1::RELATION_KIND_ABOVE;
  }
  return v1::RELATION_KIND_UNSPECIFIED;
}

void ObjectToProto(const SceneObject& o, v1::SceneObject* p) {
  p->set_id(o.id);
  p->set_label(o.label);
  SetVec(o.position, p->mutable_position());
  SetVec(o.size, p->mutable_size());
  p->set_score(o.score);
  p->set_observation_count(static_cast<uint32_t>(o.detection_count));
  p->mutable_embedding()->Assign(o.embedding.begin(), o.embedding.end());
  p->set_region_id(o.region_id);
  p->set_first_seen_ns(o.first_seen_ns);
  p->set_last_seen_ns(o.last_seen_ns);
  p->set_miss_count(static_cast<uint32_t>(std::max(o.misses, 0)));
}

void SceneToProto(const SceneSnapshot& scene, v1::SceneGraph* proto) {
  proto->set_revision(scene.revision);
  for (const SceneObject& o : scene.objects) ObjectToProto(o, proto->add_objects());
  for (const Relation& r : scene.relations) {
    auto* rel = proto->add_relations();
    rel->set_subject_id(r.subject_id);
    rel->set_kind(RelationToProto(r.kind));
    rel->set_object_id(r.object_id);
    rel->set_distance(r.distance);
  }
  for (const Region& r : scene.regions) {
    auto* region = proto->add_regions();
    region->set_id(r.id);
    region->set_name(r.name);
    region->mutable_object_ids()->Assign(r.object_ids.begin(), r.object_ids.end());
    SetVec(r.centre, region->mutable_centre());
  }
  proto->set_summary(scene.summary);
}

}  // namespace semnav::mapping
