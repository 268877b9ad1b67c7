#include "services/common/config/config_reader.h"

#include <map>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace semnav {

struct ConfigReader::Shared {
  std::vector<std::string> errors;
  // Every mapping handed out, with the keys read from it, to find unknown keys at Finish().
  std::vector<std::pair<std::string, YAML::Node>> mappings;
  std::set<std::string> used;  // full key paths
};

ConfigReader::ConfigReader(YAML::Node node, std::string path, std::shared_ptr<Shared> shared)
    : node_(std::move(node)), path_(std::move(path)), shared_(std::move(shared)) {
  if (node_ && !node_.IsMap() && !node_.IsNull()) {
    shared_->errors.push_back(
        absl::StrCat(path_.empty() ? "<root>" : path_, ": must be a mapping"));
    node_ = YAML::Node(YAML::NodeType::Map);
  }
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

absl::StatusOr<ConfigReader> ConfigReader::FromString(absl::string_view yaml) {
  try {
    return ConfigReader(YAML::Load(std::string(yaml)), "", std::make_shared<Shared>());
  } catch (const YAML::Exception& e) {
    return absl::InvalidArgumentError(absl::StrCat("config: ", e.what()));
  }
}

ConfigReader ConfigReader::Empty() {
  return ConfigReader(YAML::Node(YAML::NodeType::Map), "", std::make_shared<Shared>());
}

std::string ConfigReader::KeyPath(absl::string_view key) const {
  return path_.empty() ? std::string(key) : absl::StrCat(path_, ".", key);
}

std::optional<YAML::Node> ConfigReader::Take(absl::string_view key) {
  if (!node_ || !node_.IsMap()) return std::nullopt;
  // Const lookup: yaml-cpp's non-const operator[] would insert the key.
  const YAML::Node& map = node_;
  YAML::Node child = map[std::string(key)];
  if (!child.IsDefined()) return std::nullopt;
  shared_->used.insert(KeyPath(key));
  if (child.IsNull()) return std::nullopt;
  return child;
}

void ConfigReader::Fail(absl::string_view key, absl::string_view message) {
  shared_->errors.push_back(absl::StrCat(KeyPath(key), ": ", message));
}

std::string ConfigReader::Dump(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
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
  std::optional<YAML::Node> child = Take(key);
  return ConfigReader(child ? *child : YAML::Node(YAML::NodeType::Map), KeyPath(key), shared_);
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
    items.push_back(ConfigReader((*seq)[i], absl::StrCat(KeyPath(key), "[", i, "]"), shared_));
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
  if (!node_ || !node_.IsMap()) return keys;
  for (const auto& entry : node_) keys.push_back(KeyText(entry.first));
  return keys;
}

bool ConfigReader::Has(absl::string_view key) const {
  const YAML::Node& map = node_;
  return node_ && node_.IsMap() && map[std::string(key)];
}

void ConfigReader::Check(bool ok, absl::string_view key, absl::string_view message) {
  if (!ok) Fail(key, message);
}

absl::Status ConfigReader::Finish() const {
  std::vector<std::string> problems = shared_->errors;
  for (const auto& [path, node] : shared_->mappings) {
    if (!node || !node.IsMap()) continue;
    for (const auto& entry : node) {
      const std::string key = KeyText(entry.first);
      const std::string full = path.empty() ? key : absl::StrCat(path, ".", key);
      if (!shared_->used.contains(full)) problems.push_back(absl::StrCat(full, ": unknown key"));
    }
  }
  if (problems.empty()) return absl::OkStatus();
  return absl::InvalidArgumentError(absl::StrCat("config: ", absl::StrJoin(problems, "; ")));
}

}  // namespace semnav
