// Value checks shared by the planning requests, before any grid is read or search started:
// every number finite and of sane magnitude, every list within a budget. Failures are
// InvalidField(<dotted path>, why), e.g. "semantics.objects[2].relevance".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "semnav/common/v1/geometry.pb.h"
#include "semnav/planning/v1/exploration.pb.h"

namespace semnav::planning {

// Angles (rad): anything beyond is no heading a client meant.
inline constexpr double kMaxAngleRad = 1e3;
// Scores, weights, relevances: far above any real one, far below an overflow to infinity.
inline constexpr double kMaxScore = 1e6;
// Path lengths (m): a hundred world diameters.
inline constexpr double kMaxPathM = 100 * 2e5;
// Per-request lists (frontiers, visited poses, objects, excluded goals, path points).
inline constexpr size_t kMaxListItems = 65536;
// PlanPathRequest.contacts: the points a robot touched during one task; the gateway sends its
// newest executor.max_contacts (16 by default, at most 32).
inline constexpr int kMaxContacts = 32;
// LiveMapGrid.max_age_ms: a grid older than this is no live map.
inline constexpr uint32_t kMaxLiveGridAgeMs = 10000;

// x and y within kMaxCoordinateM, yaw within kMaxAngleRad ("<field>.x", ...).
absl::Status CheckPose2D(const semnav::common::v1::Pose2D& pose, absl::string_view field);
// Finite and |value| <= kMaxScore.
absl::Status CheckScore(double value, absl::string_view field);
// Objects (label, position, scores) and visited poses.
absl::Status CheckSemantics(const semnav::planning::v1::SemanticContext& semantics,
                            absl::string_view field);

}  // namespace semnav::planning
