#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace semnav {

// What a document is called in its errors and what an empty value means in it.
struct ConfigReaderOptions {
  // Leads every error message: "config: mapping.resolution_m: ...", "world: objects[2].id: ...".
  std::string name = "config";
  // A key given no value ("key:" or "key: ~") is absent, so it keeps its default. False for
  // data files (worlds), where an empty value is a slip: it is an error ("has no value").
  bool null_is_absent = true;
};

// Reads a YAML tree into typed settings. Absent keys keep the caller's default (Require makes
// one an error); a value of the wrong type, a failed Check, or a key nobody read makes Finish()
// fail with the full key path (e.g. "mapping.octomap.resolution_m: must be > 0"), so typos never
// pass silently. Each key gets at most one error: a Check on a key whose read failed is skipped.
class ConfigReader {
 public:
  static absl::StatusOr<ConfigReader> FromFile(const std::string& path);
  static absl::StatusOr<ConfigReader> FromString(absl::string_view yaml,
                                                 const ConfigReaderOptions& options = {});
  // A reader over an empty mapping: every Read keeps its default.
  static ConfigReader Empty();

  // Reads `key` into *value if present; records an error if it does not convert. Besides what
  // yaml-cpp converts (numbers, bool, string, std::vector of those), `value` may be a fixed-size
  // Eigen vector (a list of exactly N finite numbers, e.g. "center: [1.5, 2]") or a
  // std::vector of them (a list of such lists, e.g. a polygon); a bad element is named
  // "key[i]" / "key[i][j]". *value is left alone unless the whole value converts.
  template <typename T>
  ConfigReader& Read(absl::string_view key, T* value) {
    return ReadValue(key, value, /*required=*/false);
  }
  // As Read, but an absent key is an error ("key: missing").
  template <typename T>
  ConfigReader& Require(absl::string_view key, T* value) {
    return ReadValue(key, value, /*required=*/true);
  }

  // The subtree under `key` as YAML text, unchecked (for settings handed on to another
  // program, which checks them itself); `*yaml` is left alone when the key is absent.
  ConfigReader& ReadSubtree(absl::string_view key, std::string* yaml);

  // The mapping under `key` (an empty one when absent); errors go to the same Finish().
  ConfigReader Child(absl::string_view key);
  // As Child, but an absent key is an error ("key: missing").
  ConfigReader RequireChild(absl::string_view key);
  // The mappings of the sequence under `key`, paths "key[0]", "key[1]", ...
  std::vector<ConfigReader> Items(absl::string_view key);
  // Keys of this mapping, for sections keyed by name (e.g. backends). Reading them is up to
  // the caller (Child marks a key as used).
  std::vector<std::string> Keys() const;
  // Whether `key` is given (with or without a value); does not mark it as read.
  bool Has(absl::string_view key) const;

  // Records `message` against `key` when `ok` is false, unless `key` or this mapping already
  // has an error (a check of a value that did not read would only repeat it).
  void Check(bool ok, absl::string_view key, absl::string_view message);
  // All recorded errors plus unknown keys anywhere in the tree, or OK. The error is
  // INVALID_ARGUMENT "<name>: <path>: <why>; ..." and carries the first path as its field
  // (services/common/status/field_error.h).
  absl::Status Finish() const;

  // Full path of this reader, "" at the root.
  const std::string& path() const { return path_; }

 private:
  struct Shared;
  ConfigReader(YAML::Node node, std::string path, std::shared_ptr<Shared> shared,
               bool rejected = false);
  // The value under key, marking it used; nullopt when absent or null (a null is an error
  // when the document's nulls are not absent values).
  std::optional<YAML::Node> Take(absl::string_view key);
  // Records "missing" for an absent required key, unless this mapping is itself in error.
  void Missing(absl::string_view key);
  void Fail(absl::string_view key, absl::string_view message);
  // Records an error against a full path.
  void FailAt(const std::string& path, absl::string_view message);
  std::string KeyPath(absl::string_view key) const;
  static std::string Dump(const YAML::Node& node);
  // A mapping key as text (non-scalar keys as YAML).
  static std::string KeyText(const YAML::Node& key);

  template <typename T>
  ConfigReader& ReadValue(absl::string_view key, T* value, bool required) {
    std::optional<YAML::Node> node = Take(key);
    if (!node) {
      if (required) Missing(key);
      return *this;
    }
    if (!Convert(*node, KeyPath(key), value)) MarkFailed(KeyPath(key));
    return *this;
  }

  // Each Convert sets *value from `node` (at full path `path`) or records why not.
  template <typename T>
  bool Convert(const YAML::Node& node, const std::string& path, T* value) {
    try {
      *value = node.as<T>();
      return true;
    } catch (const YAML::Exception&) {
      FailAt(path, "has the wrong type or value '" + Dump(node) + "'");
      return false;
    }
  }
  template <int N>
  bool Convert(const YAML::Node& node, const std::string& path,
               Eigen::Matrix<double, N, 1>* value) {
    Eigen::Matrix<double, N, 1> numbers;
    if (!ConvertNumbers(node, path, N, numbers.data())) return false;
    *value = numbers;
    return true;
  }
  template <int N>
  bool Convert(const YAML::Node& node, const std::string& path,
               std::vector<Eigen::Matrix<double, N, 1>>* value) {
    if (!node.IsSequence()) {
      FailAt(path, "must be a list");
      return false;
    }
    std::vector<Eigen::Matrix<double, N, 1>> list(node.size());
    bool ok = true;
    for (std::size_t i = 0; i < list.size(); ++i) {
      ok = ConvertNumbers(node[i], ItemPath(path, i), N, list[i].data()) && ok;
    }
    if (ok) *value = std::move(list);
    return ok;
  }
  // A list of exactly `count` finite numbers into out[0..count).
  bool ConvertNumbers(const YAML::Node& node, const std::string& path, int count, double* out);
  static std::string ItemPath(const std::string& path, std::size_t i);
  // `path` has an error (Check skips it).
  void MarkFailed(const std::string& path);

  YAML::Node node_;
  std::string path_;
  std::shared_ptr<Shared> shared_;
  // This mapping's own value was rejected (not a mapping, no value, missing): its keys are
  // not reported missing on top of that.
  bool rejected_ = false;
};

}  // namespace semnav
