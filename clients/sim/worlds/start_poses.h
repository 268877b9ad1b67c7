#pragma once

#include <functional>
#include <vector>

#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/world.h"

namespace semnav::sim {

// The robot's configuration-space grid at 0.1 m for a modality flying at `altitude`
// (ground robots: 0), inflated by its radius.
GroundTruthGrid ModalityGrid(const World& world, Modality modality, double altitude);

// Cells of the largest 4-connected free region (1 = in it).
std::vector<uint8_t> LargestFreeRegion(const GroundTruthGrid& grid);

// Random start poses in the largest free region, at least 1.5 m from each other when
// possible, with random headings; only where `allowed` (when given) says yes.
using PlaceFilter = std::function<bool(const Eigen::Vector2d&)>;
std::vector<StartPose> ChooseStarts(const World& world, Modality modality, double altitude,
                                    int count, Rng& rng, const PlaceFilter& allowed = nullptr);

// Removes objects the robot cannot get within `radius` of (the success radius), so every
// target has a finite shortest path; returns how many were removed.
int RemoveUnreachableObjects(World& world, Modality modality, double altitude, double radius = 1.0);

}  // namespace semnav::sim
