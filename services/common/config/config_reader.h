#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace semnav {

// Reads a YAML tree into typed settings. Absent keys keep the caller's default; a value of
// the wrong type, a failed Check, or a key nobody read makes Finish() fail with the full key
// path (e.g. "mapping.octomap.resolution_m: must be > 0"), so typos never pass silently.
class ConfigReader {
 public:
  static absl::StatusOr<ConfigReader> FromFile(const std::string& path);
  static absl::StatusOr<ConfigReader> FromString(absl::string_view yaml);
  // A reader over an empty mapping: every Read keeps its default.
  static ConfigReader Empty();

  // Reads `key` into *value if present; records an error if it does not convert.
  template <typename T>
  ConfigReader& Read(absl::string_view key, T* value) {
    std::optional<YAML::Node> node = Take(key);
    if (!node) return *this;
    try {
      *value = node->as<T>();
    } catch (const YAML::Exception&) {
      Fail(key, "has the wrong type or value '" + Dump(*node) + "'");
    }
    return *this;
  }

  // The subtree under `key` as YAML text, unchecked (for settings handed on to another
  // program, which checks them itself); `*yaml` is left alone when the key is absent.
  ConfigReader& ReadSubtree(absl::string_view key, std::string* yaml);

  // The mapping under `key` (an empty one when absent); errors go to the same Finish().
  ConfigReader Child(absl::string_view key);
  // The mappings of the sequence under `key`, paths "key[0]", "key[1]", ...
  std::vector<ConfigReader> Items(absl::string_view key);
  // Keys of this mapping, for sections keyed by name (e.g. backends). Reading them is up to
  // the caller (Child marks a key as used).
  std::vector<std::string> Keys() const;
  bool Has(absl::string_view key) const;

  // Records `message` against `key` when `ok` is false.
  void Check(bool ok, absl::string_view key, absl::string_view message);
  // All recorded errors plus unknown keys anywhere in the tree, or OK.
  absl::Status Finish() const;

  // Full path of this reader, "" at the root.
  const std::string& path() const { return path_; }

 private:
  struct Shared;
  ConfigReader(YAML::Node node, std::string path, std::shared_ptr<Shared> shared);
  // The value under key, marking it used; nullopt when absent or null.
  std::optional<YAML::Node> Take(absl::string_view key);
  void Fail(absl::string_view key, absl::string_view message);
  std::string KeyPath(absl::string_view key) const;
  static std::string Dump(const YAML::Node& node);
  // A mapping key as text (non-scalar keys as YAML).
  static std::string KeyText(const YAML::Node& key);

  YAML::Node node_;
  std::string path_;
  std::shared_ptr<Shared> shared_;
};

}  // namespace semnav
