#include "services/reasoning/core/eroi_grid.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"

namespace semnav::reasoning {
namespace {

// Centres sit exactly on multiples of delta; the epsilon keeps 18/3 from flooring to 5.
int FloorIndex(double offset, double delta) {
  return static_cast<int>(std::floor(offset / delta + 1e-9));
}

}  // namespace

EroiGridSpec GridOverArea(const EroiGridSpec& base, const Eigen::Vector2d& lo,
                          const Eigen::Vector2d& hi) {
  EroiGridSpec spec = base;
  const Eigen::Vector2d extent = hi - lo;
  spec.delta = std::max(base.delta, extent.x() / 26.0);
  spec.min = Eigen::Vector3d(lo.x() + spec.delta / 2, lo.y() + spec.delta / 2, base.min.z());
  spec.nx = std::max(0, static_cast<int>(std::ceil(extent.x() / spec.delta - 1e-9)) - 1);
  spec.ny = std::max(0, static_cast<int>(std::ceil(extent.y() / spec.delta - 1e-9)) - 1);
  return spec;
}

absl::StatusOr<EroiGrid> EroiGrid::Create(const EroiGridSpec& spec) {
  if (!(spec.delta > 0.0)) return absl::InvalidArgumentError("eroi.delta: must be > 0");
  if (spec.nx < 0 || spec.ny < 0 || spec.nz < 0) {
    return absl::InvalidArgumentError("eroi.nx/ny/nz: must be >= 0");
  }
  if (spec.nx > 25 || spec.nz > 25) {
    return absl::InvalidArgumentError("eroi.nx/nz: codes use one letter A..Z, so at most 25");
  }
  return EroiGrid(spec);
}

Eigen::Vector3d EroiGrid::Centre(const EroiIndex& index) const {
  return spec_.min + spec_.delta * Eigen::Vector3d(index.i, index.j, index.k);
}

int EroiGrid::Flatten(const EroiIndex& index) const {
  return (index.k * (spec_.ny + 1) + index.j) * (spec_.nx + 1) + index.i;
}

EroiIndex EroiGrid::Unflatten(int flat) const {
  EroiIndex index;
  index.i = flat % (spec_.nx + 1);
  flat /= spec_.nx + 1;
  index.j = flat % (spec_.ny + 1);
  index.k = flat / (spec_.ny + 1);
  return index;
}

bool EroiGrid::Contains(const EroiIndex& index) const {
  return index.i >= 0 && index.i <= spec_.nx && index.j >= 0 && index.j <= spec_.ny &&
         index.k >= 0 && index.k <= spec_.nz;
}

EroiIndex EroiGrid::Cell(const Eigen::Vector3d& point) const {
  const Eigen::Vector3d offset = (point - spec_.min) / spec_.delta;
  return {static_cast<int>(std::lround(offset.x())), static_cast<int>(std::lround(offset.y())),
          static_cast<int>(std::lround(offset.z()))};
}

absl::StatusOr<EroiIndex> EroiGrid::Locate(const Eigen::Vector3d& point) const {
  const EroiIndex index = Cell(point);
  if (!Contains(index)) return absl::NotFoundError("point: outside the EROI grid");
  return index;
}

std::vector<int> EroiGrid::Neighbourhood(const Eigen::Vector3d& point, double radius) const {
  std::vector<int> out;
  const int reach = static_cast<int>(std::ceil(radius / spec_.delta));
  const EroiIndex centre = Cell(point);
  for (int k = centre.k - reach; k <= centre.k + reach; ++k) {
    for (int j = centre.j - reach; j <= centre.j + reach; ++j) {
      for (int i = centre.i - reach; i <= centre.i + reach; ++i) {
        const EroiIndex index{i, j, k};
        if (Contains(index) && (Centre(index) - point).norm() <= radius + 1e-9)
          out.push_back(Flatten(index));
      }
    }
  }
  return out;
}

std::string EroiGrid::Encode(const Eigen::Vector3d& centre) const {
  const int ix = FloorIndex(centre.x() - spec_.min.x(), spec_.delta);
  const int iy = FloorIndex(centre.y() - spec_.min.y(), spec_.delta) + 1;
  const int iz = FloorIndex(centre.z() - spec_.min.z(), spec_.delta);
  return absl::StrCat(std::string(1, static_cast<char>('A' + ix)), iy,
                      std::string(1, static_cast<char>('A' + iz)));
}

absl::StatusOr<Eigen::Vector3d> EroiGrid::Decode(std::string_view code) const {
  if (code.size() < 3 || !std::isalpha(static_cast<unsigned char>(code.front())) ||
      !std::isalpha(static_cast<unsigned char>(code.back()))) {
    return InvalidField("code",
                        absl::StrCat("'", std::string(code), "' is not letter-digits-letter"));
  }
  int iy = 0;
  for (char c : code.substr(1, code.size() - 2)) {
    if (!std::isdigit(static_cast<unsigned char>(c)) || iy > 100000) {
      return InvalidField("code",
                          absl::StrCat("'", std::string(code), "' is not letter-digits-letter"));
    }
    iy = iy * 10 + (c - '0');
  }
  const EroiIndex index{std::toupper(static_cast<unsigned char>(code.front())) - 'A', iy - 1,
                        std::toupper(static_cast<unsigned char>(code.back())) - 'A'};
  if (!Contains(index)) {
    return InvalidField("code", absl::StrCat("'", std::string(code), "' is outside the EROI grid"));
  }
  return Centre(index);
}

}  // namespace semnav::reasoning
