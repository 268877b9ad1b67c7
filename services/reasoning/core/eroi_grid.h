// EROI partition of the search space (seed 000, eq. 1 and 4) and the letter-digit-letter codes of
// Algorithm 1 with their inverse (eq. 14): "G5A" with delta 3 m and min (-5, -20, 0) is (13, -8,
// 0).
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::reasoning {

struct EroiGridSpec {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();  // (x_min, y_min, z_min), world frame, metres.
  double delta = 3.0;                             // EROI edge length, metres (isotropic, eq. 4).
  int nx = 0, ny = 0, nz = 0;                     // index ranges i = 0..nx, j = 0..ny, k = 0..nz.
};

struct EroiIndex {
  int i = 0, j = 0, k = 0;
  bool operator==(const EroiIndex&) const = default;
};

// `base` laid over the rectangle [lo, hi] of the map: centres from lo + delta / 2, enough of
// them to cover it, the edge widened when the area needs more than the 26 letters on x
// (delta >= width / 26); z (min, nz) stays as in `base`.
EroiGridSpec GridOverArea(const EroiGridSpec& base, const Eigen::Vector2d& lo,
                          const Eigen::Vector2d& hi);

class EroiGrid {
 public:
  // INVALID_ARGUMENT for delta <= 0, negative counts or more than 26 letters on x or z.
  static absl::StatusOr<EroiGrid> Create(const EroiGridSpec& spec);

  int size() const { return (spec_.nx + 1) * (spec_.ny + 1) * (spec_.nz + 1); }  // N of eq. 17
  Eigen::Vector3d Centre(const EroiIndex& index) const;                          // eq. 4
  Eigen::Vector3d Centre(int flat) const { return Centre(Unflatten(flat)); }
  int Flatten(const EroiIndex& index) const;
  EroiIndex Unflatten(int flat) const;
  // Index of the EROI centre nearest to `point`; NOT_FOUND outside the grid.
  absl::StatusOr<EroiIndex> Locate(const Eigen::Vector3d& point) const;
  // Flat indices of EROIs whose centre lies within `radius` of `point` (N_r(p) of eq. 18).
  std::vector<int> Neighbourhood(const Eigen::Vector3d& point, double radius) const;

  // Algorithm 1: <chr(A + i_x), i_y = floor((y - y_min) / delta) + 1, chr(A + i_z)>.
  std::string Encode(const Eigen::Vector3d& centre) const;
  // Eq. 14: the EROI centre of a code; INVALID_ARGUMENT for malformed codes or codes off the grid.
  absl::StatusOr<Eigen::Vector3d> Decode(std::string_view code) const;

  const EroiGridSpec& spec() const { return spec_; }

 private:
  explicit EroiGrid(const EroiGridSpec& spec) : spec_(spec) {}
  bool Contains(const EroiIndex& index) const;
  EroiIndex Cell(const Eigen::Vector3d& point) const;
  EroiGridSpec spec_;
};

}  // namespace semnav::reasoning
