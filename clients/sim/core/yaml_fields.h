#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <initializer_list>
#include <string>
#include <string_view>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

// Typed reads of YAML fields whose errors name the full field path ("objects[2].box.size").
namespace semnav::sim::yaml_fields {

std::string Join(const std::string& path, std::string_view key);
std::string Index(const std::string& path, size_t i);

// Error if `node` (a map at `path`) holds a key outside `allowed`.
absl::Status CheckKeys(const YAML::Node& node, const std::string& path,
                       std::initializer_list<std::string_view> allowed);
absl::Status ExpectMap(const YAML::Node& node, const std::string& path);
absl::Status ExpectSequence(const YAML::Node& node, const std::string& path);

// Missing key -> `fallback` when given, else an error naming the field.
absl::StatusOr<double> ReadDouble(const YAML::Node& map, const std::string& path,
                                  std::string_view key, const double* fallback = nullptr);
absl::StatusOr<std::string> ReadString(const YAML::Node& map, const std::string& path,
                                       std::string_view key, const std::string* fallback = nullptr);
// A fixed-length list of numbers at node (not a key).
absl::StatusOr<Eigen::VectorXd> ReadNumbers(const YAML::Node& node, const std::string& path,
                                            int count);

}  // namespace semnav::sim::yaml_fields
