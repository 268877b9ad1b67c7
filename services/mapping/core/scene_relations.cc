#include "services/mapping/core/scene_relations.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "absl/container/flat_hash_map.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace semnav::mapping {
namespace {

// Calls fn(i, j) once for every pair of objects whose centres are within `radius`: a sweep
// over the objects sorted by x, so only pairs within `radius` along x are ever compared.
template <typename Fn>
void ForPairsWithin(const std::vector<SceneObject>& objects, double radius, Fn fn) {
  std::vector<size_t> order(objects.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return objects[a].position.x() < objects[b].position.x(); });
  const double radius_sq = radius * radius;
  for (size_t a = 0; a < order.size(); ++a) {
    const Eigen::Vector3d& p = objects[order[a]].position;
    for (size_t b = a + 1; b < order.size() && objects[order[b]].position.x() - p.x() <= radius;
         ++b) {
      if ((objects[order[b]].position - p).squaredNorm() <= radius_sq) fn(order[a], order[b]);
    }
  }
}

void AddPairRelations(const SceneObject& a, const SceneObject& b, const RelationConfig& config,
                      std::vector<Relation>& out) {
  const Eigen::Vector3d d = a.position - b.position;
  const double distance = d.norm();
  out.push_back({a.id, RelationKind::kNear, b.id, distance});
  // Vertical: is one object's footprint centre inside the other's footprint?
  auto vertical = [&](const SceneObject& top, const SceneObject& base) {
    const Eigen::Vector3d off = top.position - base.position;
    if (std::abs(off.x()) > base.size.x() / 2 || std::abs(off.y()) > base.size.y() / 2)
      return false;
    const double gap =
        (top.position.z() - top.size.z() / 2) - (base.position.z() + base.size.z() / 2);
    if (std::abs(gap) <= config.on_tolerance_m) {
      out.push_back({top.id, RelationKind::kOn, base.id, distance});
      return true;
    }
    if (gap > config.on_tolerance_m) {
      out.push_back({top.id, RelationKind::kAbove, base.id, distance});
      return true;
    }
    return false;
  };
  if (vertical(a, b) || vertical(b, a)) return;
  if (std::abs(d.y()) >= std::abs(d.x()) && std::abs(d.y()) > config.direction_margin_m) {
    out.push_back(
        {a.id, d.y() > 0 ? RelationKind::kLeftOf : RelationKind::kRightOf, b.id, distance});
  } else if (std::abs(d.x()) > std::abs(d.y()) && std::abs(d.x()) > config.direction_margin_m) {
    out.push_back(
        {a.id, d.x() > 0 ? RelationKind::kInFrontOf : RelationKind::kBehind, b.id, distance});
  }
}

size_t Find(std::vector<size_t>& parent, size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<Relation> ComputeRelations(const std::vector<SceneObject>& objects,
                                       const RelationConfig& config) {
  std::vector<Relation> relations;
  ForPairsWithin(objects, config.near_m, [&](size_t i, size_t j) {
    if (objects[i].id > objects[j].id) std::swap(i, j);
    AddPairRelations(objects[i], objects[j], config, relations);
  });
  // Stable order for clients and tests: by subject, then object, then kind.
  std::sort(relations.begin(), relations.end(), [](const Relation& a, const Relation& b) {
    return std::tie(a.subject_id, a.object_id, a.kind) <
           std::tie(b.subject_id, b.object_id, b.kind);
  });
  return relations;
}

std::vector<Region> ComputeRegions(std::vector<SceneObject>& objects,
                                   const RelationConfig& config) {
  std::vector<size_t> parent(objects.size());
  std::iota(parent.begin(), parent.end(), size_t{0});
  ForPairsWithin(objects, config.region_radius_m,
                 [&](size_t i, size_t j) { parent[Find(parent, i)] = Find(parent, j); });
  // Order regions by their lowest object id so ids are stable while the graph grows.
  std::map<uint64_t, std::vector<size_t>> by_lowest_id;
  absl::flat_hash_map<size_t, uint64_t> lowest_of_root;
  for (size_t i = 0; i < objects.size(); ++i) {
    const size_t root = Find(parent, i);
    auto [it, inserted] = lowest_of_root.try_emplace(root, objects[i].id);
    if (!inserted) it->second = std::min(it->second, objects[i].id);
  }
  for (size_t i = 0; i < objects.size(); ++i)
    by_lowest_id[lowest_of_root[Find(parent, i)]].push_back(i);
  std::vector<Region> regions;
  for (const auto& [lowest, members] : by_lowest_id) {
    Region region;
    region.id = static_cast<int>(regions.size());
    std::map<std::string, int> label_counts;
    for (size_t i : members) {
      objects[i].region_id = region.id;
      region.object_ids.push_back(objects[i].id);
      region.centre += objects[i].position / static_cast<double>(members.size());
      ++label_counts[objects[i].label];
    }
    std::vector<std::pair<int, std::string>> ranked;
    for (const auto& [label, n] : label_counts) ranked.push_back({-n, label});
    std::sort(ranked.begin(), ranked.end());
    std::vector<std::string> top;
    for (size_t k = 0; k < ranked.size() && k < 2; ++k) top.push_back(ranked[k].second);
    region.name = absl::StrCat("area_with_", absl::StrJoin(top, "_"));
    regions.push_back(std::move(region));
  }
  return regions;
}

std::string Summarize(const std::vector<SceneObject>& objects, const std::vector<Region>& regions) {
  absl::flat_hash_map<uint64_t, const SceneObject*> by_id;
  for (const SceneObject& o : objects) by_id[o.id] = &o;
  std::string text =
      absl::StrCat("Scene has ", objects.size(), " objects in ", regions.size(), " regions.");
  for (const Region& region : regions) {
    std::map<std::string, int> counts;
    for (uint64_t id : region.object_ids) ++counts[by_id[id]->label];
    std::vector<std::string> parts;
    for (const auto& [label, n] : counts) parts.push_back(absl::StrCat(n, " ", label));
    absl::StrAppend(&text, " Region ", region.id, " (", region.name,
                    "): ", absl::StrJoin(parts, ", "), ".");
  }
  return text;
}

}  // namespace semnav::mapping
