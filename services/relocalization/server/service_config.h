#pragma once

#include <cstddef>
#include <string>

#include "absl/status/statusor.h"
#include "services/common/config/config_reader.h"
#include "services/relocalization/core/landmark_map.h"
#include "services/relocalization/core/object_points.h"
#include "services/relocalization/core/onnx_heads.h"
#include "services/relocalization/core/relocalizer.h"

namespace semnav::relocalization {

// Settings of semnav-relocalization (YAML section "relocalization"); every default is the
// seed-001 parameter set documented in docs/algorithms/relocalization.md.
struct ServiceConfig {
  std::string storage_dir;              // landmark map files; empty = memory only
  size_t idempotency_cache = 1024;      // remembered request_id answers
  ObjectPointParams object_points;      // "object_points"
  OnnxHeadsConfig detector;             // "detector"; model_path empty = no ONNX detector
  MergeParams merge;                    // "merge"
  RelocalizationParams relocalization;  // "matching", "pose", "reliability", rematch_rounds

  static absl::StatusOr<ServiceConfig> FromYaml(ConfigReader& section);
};

}  // namespace semnav::relocalization
