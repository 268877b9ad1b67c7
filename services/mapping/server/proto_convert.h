#pragma once

#include <vector>

#include "absl/status/statusor.h"
#include "semnav/mapping/v1/mapping_service.pb.h"
#include "services/mapping/core/grid_layers.h"
#include "services/mapping/core/mapping_engine.h"
#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping {

// Proto frame -> core frame. Only what the core cannot see is checked here (image encodings of
// rgb and masks, mask sizes); everything else is ValidateFrame's job.
absl::StatusOr<SensorFrame> FrameFromProto(const v1::SensorFrame& proto);

// Layers of `kinds` (empty = all) into a GridMap.
semnav::common::v1::GridMap GridToProto(
    const GridLayers& layers, uint64_t revision,
    const std::vector<semnav::common::v1::GridLayerKind>& kinds);

void ObjectToProto(const SceneObject& object, v1::SceneObject* proto);
void SceneToProto(const SceneSnapshot& scene, v1::SceneGraph* proto);
v1::RelationKind RelationToProto(RelationKind kind);

// INVALID_ARGUMENT naming `field` unless every kind is a defined, specified GridLayerKind.
absl::Status CheckLayerKinds(const google::protobuf::RepeatedField<int>& kinds,
                             absl::string_view field);

}  // namespace semnav::mapping
