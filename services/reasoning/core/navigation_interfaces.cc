#include "services/reasoning/core/navigation_interfaces.h"

#include "absl/strings/cord.h"
#include "absl/strings/str_cat.h"

namespace semnav::reasoning {
namespace {

// Payload key of the dependency's name: the message stays free for the cause.
constexpr char kDependencyPayload[] = "type.semnav.dev/reasoning.UnavailableDependency";

}  // namespace

double HorizontalLength(const Eigen::Vector3d& from, const std::vector<Eigen::Vector3d>& path) {
  double length = 0.0;
  Eigen::Vector3d at = from;
  for (const Eigen::Vector3d& point : path) {
    length += (point - at).head<2>().norm();
    at = point;
  }
  return length;
}

absl::Status DependencyUnavailableError(absl::string_view dependency, absl::string_view detail) {
  absl::Status status = absl::UnavailableError(absl::StrCat(dependency, " unavailable: ", detail));
  status.SetPayload(kDependencyPayload, absl::Cord(dependency));
  return status;
}

std::string UnavailableDependency(const absl::Status& status) {
  const auto named = status.GetPayload(kDependencyPayload);
  return named.has_value() ? std::string(*named) : "planning";
}

}  // namespace semnav::reasoning
