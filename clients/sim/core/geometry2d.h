#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "clients/sim/core/world.h"
#include "services/common/geometry/segment.h"

// Small 2D helpers on footprints (the xy plane).
namespace semnav::sim {

using Polygon2 = std::vector<Eigen::Vector2d>;

bool PointInPolygon(const Polygon2& polygon, const Eigen::Vector2d& point);
double PolygonArea(const Polygon2& polygon);  // absolute value
using semnav::geometry::DistanceToSegment;
// Distance from a point to the polygon boundary (0 on the edge, also inside).
double DistanceToPolygonBoundary(const Polygon2& polygon, const Eigen::Vector2d& point);
// Four footprint corners of a box, counter-clockwise.
std::array<Eigen::Vector2d, 4> BoxCorners(const BoxShape& box);
// Distance from a point to a box footprint (0 inside).
double DistanceToBoxFootprint(const BoxShape& box, const Eigen::Vector2d& point);
// True if two box footprints, each grown by `clearance` on every side, overlap (separating
// axis test on the four edge normals).
bool FootprintsOverlap(const BoxShape& a, const BoxShape& b, double clearance);
// Axis-aligned bounds of a shape footprint: (min, max).
std::pair<Eigen::Vector2d, Eigen::Vector2d> FootprintBounds(const Shape& shape);

}  // namespace semnav::sim
