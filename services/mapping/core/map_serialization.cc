#include "services/mapping/core/map_serialization.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "absl/strings/str_cat.h"

namespace semnav::mapping {
namespace {

using nlohmann::json;

void PutSection(std::string& out, const std::string& section) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((section.size() >> (8 * i)) & 0xff));
  out += section;
}

absl::StatusOr<std::string> TakeSection(const std::string& in, size_t& offset,
                                        absl::string_view name) {
  if (in.size() - offset < 8)
    return absl::DataLossError(absl::StrCat("map payload: ", name, " section missing"));
  uint64_t size = 0;
  for (int i = 0; i < 8; ++i)
    size |= static_cast<uint64_t>(static_cast<unsigned char>(in[offset + i])) << (8 * i);
  offset += 8;
  if (in.size() - offset < size)
    return absl::DataLossError(absl::StrCat("map payload: ", name, " section truncated"));
  std::string section = in.substr(offset, size);
  offset += size;
  return section;
}

constexpr size_t kSavedCellBytes = 4 + 4 + 4 + 1 + 1;

void PutLe(std::string& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

uint64_t GetLe(const std::string& in, size_t offset, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) {
    value |= static_cast<uint64_t>(static_cast<unsigned char>(in[offset + i])) << (8 * i);
  }
  return value;
}

std::string GridSection(const SavedGrid& grid) {
  std::string out;
  out.reserve(16 + grid.cells.size() * kSavedCellBytes);
  PutLe(out, std::bit_cast<uint64_t>(grid.resolution_m), 8);
  PutLe(out, grid.cells.size(), 8);
  for (const SavedGridCell& cell : grid.cells) {
    PutLe(out, static_cast<uint32_t>(cell.x), 4);
    PutLe(out, static_cast<uint32_t>(cell.y), 4);
    PutLe(out, std::bit_cast<uint32_t>(cell.log_odds), 4);
    PutLe(out, cell.height, 1);
    PutLe(out, cell.structure ? 1 : 0, 1);
  }
  return out;
}

absl::StatusOr<SavedGrid> ParseGridSection(const std::string& section) {
  if (section.size() < 16) return absl::DataLossError("map payload: grid section truncated");
  SavedGrid grid;
  grid.resolution_m = std::bit_cast<double>(GetLe(section, 0, 8));
  const uint64_t count = GetLe(section, 8, 8);
  if (!std::isfinite(grid.resolution_m) || grid.resolution_m <= 0.0) {
    return absl::DataLossError("map payload: grid resolution is not a positive number");
  }
  // Division, not multiplication: a corrupt count must not overflow the size check.
  const size_t cell_bytes = section.size() - 16;
  if (cell_bytes % kSavedCellBytes != 0 || cell_bytes / kSavedCellBytes != count) {
    return absl::DataLossError(absl::StrCat("map payload: grid section holds ", section.size() - 16,
                                            " bytes for ", count, " cells"));
  }
  grid.cells.resize(count);
  size_t offset = 16;
  for (SavedGridCell& cell : grid.cells) {
    cell.x = static_cast<int32_t>(static_cast<uint32_t>(GetLe(section, offset, 4)));
    cell.y = static_cast<int32_t>(static_cast<uint32_t>(GetLe(section, offset + 4, 4)));
    cell.log_odds = std::bit_cast<float>(static_cast<uint32_t>(GetLe(section, offset + 8, 4)));
    cell.height = static_cast<uint8_t>(GetLe(section, offset + 12, 1));
    const uint64_t structure = GetLe(section, offset + 13, 1);
    if (!std::isfinite(cell.log_odds) || structure > 1) {
      return absl::DataLossError(
          absl::StrCat("map payload: grid cell (", cell.x, ", ", cell.y, ") is malformed"));
    }
    cell.structure = structure == 1;
    offset += kSavedCellBytes;
  }
  return grid;
}

// nlohmann's get<> turns a float into an integer or a float by a plain cast, undefined when the
// value does not fit (a corrupt "count": 1e300): stored numbers are checked before conversion.
struct MalformedNumber : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <typename Int>
Int IntegerOf(const json& j, const char* name) {
  if (j.is_number_unsigned()) {
    const uint64_t v = j.get<uint64_t>();
    if (v <= static_cast<uint64_t>(std::numeric_limits<Int>::max())) return static_cast<Int>(v);
  } else if (j.is_number_integer()) {
    const int64_t v = j.get<int64_t>();
    if (v >= static_cast<int64_t>(std::numeric_limits<Int>::min()) &&
        (v < 0 ||
         static_cast<uint64_t>(v) <= static_cast<uint64_t>(std::numeric_limits<Int>::max()))) {
      return static_cast<Int>(v);
    }
  }
  throw MalformedNumber(absl::StrCat(name, " is not an integer in range"));
}

std::vector<float> FloatsOf(const json& j, const char* name) {
  if (!j.is_array()) throw MalformedNumber(absl::StrCat(name, " is not a list of numbers"));
  std::vector<float> values;
  values.reserve(j.size());
  for (const json& v : j) {
    if (!v.is_number() || !(std::abs(v.get<double>()) <= std::numeric_limits<float>::max())) {
      throw MalformedNumber(absl::StrCat(name, " holds a value that is not a float"));
    }
    values.push_back(static_cast<float>(v.get<double>()));
  }
  return values;
}

// The semantic points as the JSON object {"label": [x, y, z, ...], ...}, written straight into a
// string: a json tree of 16-byte values per coordinate was the live snapshot's largest transient
// (hundreds of thousands of points every 5 s in the fleet soak).
std::string SemanticSection(const std::map<std::string, std::vector<Eigen::Vector3f>>& points) {
  std::size_t count = 0;
  for (const auto& [label, label_points] : points) count += label_points.size();
  std::string out;
  out.reserve(2 + points.size() * 32 + count * 3 * 20);
  out.push_back('{');
  char number[32];
  for (const auto& [label, label_points] : points) {
    if (out.size() > 1) out.push_back(',');
    out += json(label).dump();  // escaped as JSON wants
    out += ":[";
    for (std::size_t i = 0; i < label_points.size(); ++i) {
      for (int axis = 0; axis < 3; ++axis) {
        if (i > 0 || axis > 0) out.push_back(',');
        // The double's shortest text, as the json writer gave: it reads back to the same
        // double and so to the same float.
        const std::to_chars_result written = std::to_chars(
            number, number + sizeof(number), static_cast<double>(label_points[i][axis]));
        out.append(number, written.ptr);
        // "-0" would read back as the integer 0: like the json writer, mark it a float.
        if (std::find_if(number, written.ptr, [](char c) { return c == '.' || c == 'e'; }) ==
            written.ptr) {
          out += ".0";
        }
      }
    }
    out.push_back(']');
  }
  out.push_back('}');
  return out;
}

json Vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }
Eigen::Vector3d Vec(const json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

}  // namespace

std::string OctreeSection(const octomap::OcTree& tree) {
  std::ostringstream octree;
  tree.write(octree);
  return std::move(octree).str();
}

std::string SerializeMap(const octomap::OcTree& tree, const std::vector<SceneObject>& objects,
                         uint64_t next_object_id,
                         const std::map<std::string, std::vector<Eigen::Vector3f>>& semantic_points,
                         const SavedGrid* grid) {
  return SerializeMap(OctreeSection(tree), objects, next_object_id, semantic_points, grid);
}

std::string SerializeMap(std::string octree_section, const std::vector<SceneObject>& objects,
                         uint64_t next_object_id,
                         const std::map<std::string, std::vector<Eigen::Vector3f>>& semantic_points,
                         const SavedGrid* grid) {
  json scene = {{"next_id", next_object_id}, {"objects", json::array()}};
  for (const SceneObject& o : objects) {
    scene["objects"].push_back({{"id", o.id},
                                {"label", o.label},
                                {"position", Vec(o.position)},
                                {"size", Vec(o.size)},
                                {"score", o.score},
                                {"count", o.detection_count},
                                {"embedding", o.embedding},
                                {"first_seen_ns", o.first_seen_ns},
                                {"last_seen_ns", o.last_seen_ns}});
  }
  // Every section first, then one payload of exactly their size: appending to a growing string
  // held up to twice the payload at once, every live snapshot (docs/performance.md, "Fleet").
  const std::string scene_section = scene.dump();
  const std::string semantic_section = SemanticSection(semantic_points);
  const std::string grid_section = grid != nullptr ? GridSection(*grid) : std::string();
  std::string out;
  out.reserve(4 * 8 + octree_section.size() + scene_section.size() + semantic_section.size() +
              grid_section.size());
  PutSection(out, octree_section);
  PutSection(out, scene_section);
  PutSection(out, semantic_section);
  if (grid != nullptr) PutSection(out, grid_section);
  return out;
}

absl::StatusOr<MapContent> ParseMap(const std::string& payload) {
  size_t offset = 0;
  absl::StatusOr<std::string> octree = TakeSection(payload, offset, "octree");
  if (!octree.ok()) return octree.status();
  absl::StatusOr<std::string> scene = TakeSection(payload, offset, "scene");
  if (!scene.ok()) return scene.status();
  absl::StatusOr<std::string> semantic = TakeSection(payload, offset, "semantic");
  if (!semantic.ok()) return semantic.status();

  MapContent content;
  // Files saved before the grid was kept end here.
  if (offset < payload.size()) {
    absl::StatusOr<std::string> grid = TakeSection(payload, offset, "grid");
    if (!grid.ok()) return grid.status();
    absl::StatusOr<SavedGrid> parsed = ParseGridSection(*grid);
    if (!parsed.ok()) return parsed.status();
    content.grid = *std::move(parsed);
  }
  std::istringstream octree_stream(*octree);
  std::unique_ptr<octomap::AbstractOcTree> tree(octomap::AbstractOcTree::read(octree_stream));
  auto* oc_tree = dynamic_cast<octomap::OcTree*>(tree.get());
  if (oc_tree == nullptr)
    return absl::DataLossError("map payload: octree section is not an OcTree");
  tree.release();
  content.tree.reset(oc_tree);
  try {
    const json scene_json = json::parse(*scene);
    content.next_object_id = IntegerOf<uint64_t>(scene_json.at("next_id"), "next_id");
    for (const json& j : scene_json.at("objects")) {
      SceneObject o;
      o.id = IntegerOf<uint64_t>(j.at("id"), "id");
      o.label = j.at("label").get<std::string>();
      o.position = Vec(j.at("position"));
      o.size = Vec(j.at("size"));
      o.score = j.at("score").get<double>();
      o.detection_count = IntegerOf<int>(j.at("count"), "count");
      o.embedding = FloatsOf(j.at("embedding"), "embedding");
      o.first_seen_ns = IntegerOf<int64_t>(j.at("first_seen_ns"), "first_seen_ns");
      o.last_seen_ns = IntegerOf<int64_t>(j.at("last_seen_ns"), "last_seen_ns");
      content.objects.push_back(std::move(o));
    }
    const json semantic_json = json::parse(*semantic);
    for (const auto& [label, flat] : semantic_json.items()) {
      const std::vector<float> values = FloatsOf(flat, "semantic points");
      if (values.size() % 3 != 0)
        return absl::DataLossError("map payload: semantic points not in xyz triples");
      auto& points = content.semantic_points[label];
      for (size_t i = 0; i + 2 < values.size(); i += 3)
        points.emplace_back(values[i], values[i + 1], values[i + 2]);
    }
  } catch (const json::exception& e) {
    return absl::DataLossError(absl::StrCat("map payload: ", e.what()));
  } catch (const MalformedNumber& e) {
    return absl::DataLossError(absl::StrCat("map payload: ", e.what()));
  }
  return content;
}

}  // namespace semnav::mapping
