#include "services/common/config/config_reader.h"

#include <cmath>

#include "absl/strings/cord.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "services/common/status/field_error.h"

namespace semnav {

struct ConfigReader::Shared {
  ConfigReaderOptions options;
  // (full path, why), in the order found; the root's path is "".
  std::vector<std::pair<std::string, std::string>> errors;
  std::set<std::string> failed;  // full paths with an error
  // Every mapping handed out, with the keys read from it, to find unknown keys at Finish().
  std::vector<std::pair<std::string, YAML::Node>> mappings;
  std::set<std::string> used;  // full key paths
};

ConfigReader::ConfigReader(YAML::Node node, std::string path, std::shared_ptr<Shared> shared,
                           bool rejected)
    : node_(std::move(node)),
      path_(std::move(path)),
      shared_(std::move(shared)),
      rejected_(rejected) {
  // A null item of a list ("[~]") is no mapping where nulls are not absent values.
  if (node_ && !node_.IsMap() && !(node_.IsNull() && shared_->options.null_is_absent)) {
    FailAt(path_, "must be a mapping");
    rejected_ = true;
  }
  if (!node_ || !node_.IsMap()) node_ = YAML::Node(YAML::NodeType::Map);
  shared_->mappings.emplace_back(path_, node_);
}

absl::StatusOr<ConfigReader> ConfigReader::FromFile(const std::string& path) {
  try {
    return ConfigReader(YAML::LoadFile(path), "", std::make_shared<Shared>());
  } catch (const YAML::BadFile&) {
    return absl::NotFoundError(absl::StrCat("config file '", path, "' cannot be read"));
  } catch (const YAML::Exception& e) {
    return absl::InvalidArgumentError(absl::StrCat("config file '", path, "': ", e.what()));
  }
}

absl::StatusOr<ConfigReader> ConfigReader::FromString(absl::string_view yaml,
                                                      const ConfigReaderOptions& options) {
  try {
    auto shared = std::make_shared<Shared>();
    shared->options = options;
    return ConfigReader(YAML::Load(std::string(yaml)), "", std::move(shared));
  } catch (const YAML::Exception& e) {
    return absl::InvalidArgumentError(absl::StrCat(options.name, ": ", e.what()));
  }
}

ConfigReader ConfigReader::Empty() {
  return ConfigReader(YAML::Node(YAML::NodeType::Map), "", std::make_shared<Shared>());
}

std::string ConfigReader::KeyPath(absl::string_view key) const {
  return path_.empty() ? std::string(key) : absl::StrCat(path_, ".", key);
}

std::string ConfigReader::ItemPath(const std::string& path, std::size_t i) {
  return absl::StrCat(path, "[", i, "]");
}

std::optional<YAML::Node> ConfigReader::Take(absl::string_view key) {
  // Const lookup: yaml-cpp's non-const operator[] would insert the key.
  const YAML::Node& map = node_;
  YAML::Node child = map[std::string(key)];
  if (!child.IsDefined()) return std::nullopt;
  shared_->used.insert(KeyPath(key));
  if (child.IsNull()) {
    if (!shared_->options.null_is_absent) Fail(key, "has no value");
    return std::nullopt;
  }
  return child;
}

void ConfigReader::Missing(absl::string_view key) {
  // A key given without a value has its error already.
  if (!rejected_ && !shared_->failed.contains(KeyPath(key))) Fail(key, "missing");
}

void ConfigReader::Fail(absl::string_view key, absl::string_view message) {
  FailAt(KeyPath(key), message);
}

void ConfigReader::FailAt(const std::string& path, absl::string_view message) {
  shared_->errors.emplace_back(path, std::string(message));
  MarkFailed(path);
}

void ConfigReader::MarkFailed(const std::string& path) { shared_->failed.insert(path); }

std::string ConfigReader::Dump(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

bool ConfigReader::ConvertNumbers(const YAML::Node& node, const std::string& path, int count,
                                  double* out) {
  if (!node.IsSequence() || static_cast<int>(node.size()) != count) {
    FailAt(path, absl::StrCat("expected a list of ", count, " numbers"));
    return false;
  }
  for (int i = 0; i < count; ++i) {
    // convert<double> accepts ".inf" and ".nan"; no coordinate is either.
    if (!YAML::convert<double>::decode(node[i], out[i]) || !std::isfinite(out[i])) {
      FailAt(ItemPath(path, i), "expected a finite number");
      return false;
    }
  }
  return true;
}

ConfigReader& ConfigReader::ReadSubtree(absl::string_view key, std::string* yaml) {
  std::optional<YAML::Node> node = Take(key);
  if (!node) return *this;
  YAML::Emitter out;
  out << *node;
  *yaml = out.c_str();
  return *this;
}

ConfigReader ConfigReader::Child(absl::string_view key) {
  const bool given = Has(key);
  std::optional<YAML::Node> child = Take(key);
  // A child given without a value is rejected already when nulls are errors.
  return ConfigReader(child ? *child : YAML::Node(YAML::NodeType::Map), KeyPath(key), shared_,
                      given && !child && !shared_->options.null_is_absent);
}

ConfigReader ConfigReader::RequireChild(absl::string_view key) {
  const bool given = Has(key);
  ConfigReader child = Child(key);
  if (!given) {
    Missing(key);
    child.rejected_ = true;
  }
  return child;
}

std::vector<ConfigReader> ConfigReader::Items(absl::string_view key) {
  std::vector<ConfigReader> items;
  std::optional<YAML::Node> seq = Take(key);
  if (!seq) return items;
  if (!seq->IsSequence()) {
    Fail(key, "must be a list");
    return items;
  }
  for (std::size_t i = 0; i < seq->size(); ++i) {
    items.push_back(ConfigReader((*seq)[i], ItemPath(KeyPath(key), i), shared_));
  }
  return items;
}

std::string ConfigReader::KeyText(const YAML::Node& key) {
  // A non-scalar key ("{[1]: 2}") has no string form: as<std::string>() would throw. It is shown
  // as YAML, and no reader asks for it, so it is reported as unknown.
  return key.IsScalar() ? key.Scalar() : Dump(key);
}

std::vector<std::string> ConfigReader::Keys() const {
  std::vector<std::string> keys;
  for (const auto& entry : node_) keys.push_back(KeyText(entry.first));
  return keys;
}

bool ConfigReader::Has(absl::string_view key) const {
  const YAML::Node& map = node_;
  return static_cast<bool>(map[std::string(key)]);
}

void ConfigReader::Check(bool ok, absl::string_view key, absl::string_view message) {
  // A mapping in error has its message already; its values are defaults.
  if (!ok && !rejected_ && !shared_->failed.contains(KeyPath(key))) Fail(key, message);
}

absl::Status ConfigReader::Finish() const {
  std::vector<std::pair<std::string, std::string>> problems = shared_->errors;
  for (const auto& [path, node] : shared_->mappings) {
    for (const auto& entry : node) {
      const std::string key = KeyText(entry.first);
      const std::string full = path.empty() ? key : absl::StrCat(path, ".", key);
      if (!shared_->used.contains(full)) problems.emplace_back(full, "unknown key");
    }
  }
  if (problems.empty()) return absl::OkStatus();
  std::vector<std::string> lines;
  for (const auto& [path, why] : problems) {
    lines.push_back(absl::StrCat(path.empty() ? "<root>" : path, ": ", why));
  }
  absl::Status status = absl::InvalidArgumentError(
      absl::StrCat(shared_->options.name, ": ", absl::StrJoin(lines, "; ")));
  if (!problems.front().first.empty()) {
    status.SetPayload(kFieldPayloadUrl, absl::Cord(problems.front().first));
    status.SetPayload(kReasonPayloadUrl, absl::Cord("FIELD_INVALID"));
  }
  return status;
}

}  // namespace semnav
