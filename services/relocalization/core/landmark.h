#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"

namespace semnav::relocalization {

// A generalized-object descriptor (seed 001, 1.2): one similarity per label or a
// learned feature vector; its arg-max is the landmark's "most similar label".
using Descriptor = std::vector<float>;

// A 3D landmark reconstructed from a generalized object point.
struct Landmark {
  uint64_t id = 0;                                   // 0 = not yet stored in a map
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // metres, map (or query) frame
  double scale = 0.0;                                // metric object size, metres
  Descriptor descriptor;
  uint32_t observations = 1;                         // frames fused into this landmark
};

// Index of the largest descriptor entry (the hash key of seed 001, 3.1); -1 if empty.
int DescriptorLabel(const Descriptor& descriptor);

// Cosine similarity in [-1, 1]; 0 when either vector has zero norm.
double CosineSimilarity(const Descriptor& a, const Descriptor& b);

// Checks finite position, positive finite scale and a finite descriptor (named
// "embedding" in errors, its wire name) of
// `descriptor_dim` entries (0 = any non-empty length). Errors name `field`.
absl::Status ValidateLandmark(const Landmark& landmark, size_t descriptor_dim,
                              absl::string_view field);

}  // namespace semnav::relocalization
