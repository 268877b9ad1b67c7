#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/world.h"

namespace semnav::sim {

// The robot's configuration-space grid at 0.1 m for a modality flying at `altitude`
// (ground robots: 0), inflated by its radius.
GroundTruthGrid ModalityGrid(const World& world, Modality modality, double altitude);

// Cells of the largest 4-connected free region (1 = in it).
std::vector<uint8_t> LargestFreeRegion(const GroundTruthGrid& grid);

using PlaceFilter = std::function<bool(const Eigen::Vector2d&)>;

// Clearance a start needs (docs/algorithms/simulation.md, "Start poses"). Habitat draws ObjectNav
// starts on a navmesh eroded by the agent radius, and habitat-lab's episode generator rejects a
// start whose navmesh island is smaller than ISLAND_RADIUS_LIMIT = 1.5 m. Here the erosion is the
// robot's radius plus `margin_m`: a start has clearance when no solid of the body's height band
// comes within radius + margin of it, and its 4-connected free region of the raster dilated by
// radius + margin (its island) reaches at least `min_island_radius_m` from the island's centroid,
// so it is not in a pocket whose ways out are narrower than the clearance.
struct StartClearance {
  // One cell of the 0.1 m raster the starts are drawn on: the draw's one-cell rule, made exact.
  double margin_m = 0.1;
  double min_island_radius_m = 1.5;  // habitat-lab ISLAND_RADIUS_LIMIT
};

// Where a drawn start moves when it lacks clearance: the nearest place with clearance by
// 4-connected steps through the largest free region of the body's raster (so it stays joined to
// every target the draw could reach), ties broken by a fixed neighbour order; no randomness, so
// a start that has clearance, and every other draw, stays as it was.
class StartClearanceSearch {
 public:
  StartClearanceSearch(const World& world, Modality modality, double altitude,
                       const StartClearance& clearance, PlaceFilter allowed = nullptr);
  // True when no solid of the body's height band comes within radius + margin of `place` and
  // `place` lies on an island of at least the minimum radius.
  bool Clear(const Eigen::Vector2d& place) const;
  // `drawn` itself when it has clearance; else the nearest cell centre with clearance (and
  // allowed); nullopt when none is reachable from `drawn`'s cell.
  std::optional<Eigen::Vector2d> Nearest(const Eigen::Vector2d& drawn) const;
  const GroundTruthGrid& grid() const { return grid_; }
  const std::vector<uint8_t>& region() const { return region_; }

 private:
  GroundTruthGrid grid_;            // dilated by the radius
  std::vector<uint8_t> region_;     // its largest free region
  GroundTruthGrid clear_grid_;      // dilated by radius + margin
  std::vector<uint8_t> on_island_;  // its free cells on an island of the minimum radius
  Scene scene_;
  double radius_m_ = 0.0;
  double z0_ = 0.0, z1_ = 0.0;
  PlaceFilter allowed_;
};

// Random start poses in the largest free region, at least 1.5 m from each other when
// possible (as drawn), with random headings; only where `allowed` (when given) says yes. A draw
// without clearance moves to StartClearanceSearch::Nearest (kept as drawn when none is found).
std::vector<StartPose> ChooseStarts(const World& world, Modality modality, double altitude,
                                    int count, Rng& rng, const PlaceFilter& allowed = nullptr,
                                    const StartClearance& clearance = {});

// Removes objects the robot cannot get within `radius` of (the success radius), so every
// target has a finite shortest path; returns how many were removed.
int RemoveUnreachableObjects(World& world, Modality modality, double altitude, double radius = 1.0);

}  // namespace semnav::sim
