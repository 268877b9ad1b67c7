#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"

namespace semnav::relocalization {

// A generalized-object descriptor (seed 001, 1.2): one similarity per label or a
// learned feature vector; its arg-max is the landmark's "most similar label".
using Descriptor = std::vector<float>;

// A 3D landmark reconstructed from a generalized object point.
struct Landmark {
  uint64_t id = 0;                                     // 0 = not yet stored in a map
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // metres, map (or query) frame
  double scale = 0.0;                                  // metric object size, metres
  Descriptor descriptor;
  uint32_t observations = 1;  // frames fused into this landmark
};

// Index of the largest descriptor entry (the hash key of seed 001, 3.1); -1 if empty.
int DescriptorLabel(const Descriptor& descriptor);

// Indices of the `count` largest descriptor entries, largest first (ties: lower index
// first); fewer when the descriptor is shorter. Entry 0 is DescriptorLabel.
std::vector<int> TopDescriptorLabels(const Descriptor& descriptor, size_t count);

// Cosine similarity in [-1, 1]; 0 when either vector has zero norm.
double CosineSimilarity(const Descriptor& a, const Descriptor& b);

// Request limits (docs/protocol.md, Relocalization): bounds that keep one request's memory and
// arithmetic sane (squared distances and descriptor dot products stay far from overflow).
inline constexpr double kMaxLandmarkScaleM = 1e3;         // no object is larger than 1 km
inline constexpr size_t kMaxDescriptorDim = 4096;         // floats per embedding
inline constexpr double kMaxDescriptorValue = 1e6;        // |each embedding entry|
inline constexpr uint32_t kMaxObservations = 1000000;     // fused frames; sums stay in uint32
inline constexpr size_t kMaxLandmarksPerRequest = 10000;  // upserted or observed landmarks

// Checks each position coordinate within +-kMaxCoordinateM, scale in (0, kMaxLandmarkScaleM],
// observations <= kMaxObservations and a descriptor (named "embedding" in errors, its wire
// name) of 1..kMaxDescriptorDim entries, each within +-kMaxDescriptorValue, of
// `descriptor_dim` entries (0 = any non-empty length). Errors name `field` and its sub-field
// ("landmarks[3].position.x") via InvalidField.
absl::Status ValidateLandmark(const Landmark& landmark, size_t descriptor_dim,
                              absl::string_view field);

}  // namespace semnav::relocalization
