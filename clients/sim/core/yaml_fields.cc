#include "clients/sim/core/yaml_fields.h"

#include <cmath>

#include "absl/strings/str_cat.h"

namespace semnav::sim::yaml_fields {
namespace {

absl::Status Bad(const std::string& path, std::string_view what) {
  return absl::InvalidArgumentError(
      absl::StrCat(path, ": ", absl::string_view(what.data(), what.size())));
}

}  // namespace

std::string Join(const std::string& path, std::string_view key) {
  std::string k(key);
  return path.empty() ? k : absl::StrCat(path, ".", k);
}

std::string Index(const std::string& path, size_t i) { return absl::StrCat(path, "[", i, "]"); }

// IsMap()/IsSequence() throw YAML::InvalidNode on the invalid node a lookup in a non-map gives
// (found by tests/fuzz, world_yaml): IsDefined() is false for it and safe to ask.
absl::Status ExpectMap(const YAML::Node& node, const std::string& path) {
  if (!node.IsDefined() || !node.IsMap())
    return Bad(path.empty() ? "world" : path, "expected a mapping");
  return absl::OkStatus();
}

absl::Status ExpectSequence(const YAML::Node& node, const std::string& path) {
  if (!node.IsDefined() || !node.IsSequence()) return Bad(path, "expected a list");
  return absl::OkStatus();
}

absl::Status CheckKeys(const YAML::Node& node, const std::string& path,
                       std::initializer_list<std::string_view> allowed) {
  for (const auto& entry : node) {
    // A non-scalar key ("{[1]: 2}") is never allowed; as<std::string>() would throw on it.
    if (!entry.first.IsScalar()) return Bad(path, "a key must be a plain name");
    const std::string key = entry.first.Scalar();
    bool known = false;
    for (std::string_view a : allowed) known = known || a == key;
    if (!known) return Bad(Join(path, key), "unknown field");
  }
  return absl::OkStatus();
}

absl::StatusOr<double> ReadDouble(const YAML::Node& map, const std::string& path,
                                  std::string_view key, const double* fallback) {
  const std::string field = Join(path, key);
  const YAML::Node node = map[std::string(key)];
  if (!node) {
    if (fallback != nullptr) return *fallback;
    return Bad(field, "missing");
  }
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    return Bad(field, "expected a finite number");
  }
  return value;
}

absl::StatusOr<std::string> ReadString(const YAML::Node& map, const std::string& path,
                                       std::string_view key, const std::string* fallback) {
  const std::string field = Join(path, key);
  const YAML::Node node = map[std::string(key)];
  if (!node) {
    if (fallback != nullptr) return *fallback;
    return Bad(field, "missing");
  }
  if (!node.IsScalar()) return Bad(field, "expected a string");
  return node.as<std::string>();
}

absl::StatusOr<Eigen::VectorXd> ReadNumbers(const YAML::Node& node, const std::string& path,
                                            int count) {
  if (!node || !node.IsSequence() || static_cast<int>(node.size()) != count) {
    return Bad(path, absl::StrCat("expected a list of ", count, " numbers"));
  }
  Eigen::VectorXd values(count);
  for (int i = 0; i < count; ++i) {
    double v = 0.0;
    if (!node[i].IsScalar() || !YAML::convert<double>::decode(node[i], v) || !std::isfinite(v)) {
      return Bad(Index(path, i), "expected a finite number");
    }
    values[i] = v;
  }
  return values;
}

}  // namespace semnav::sim::yaml_fields
