#pragma once

#include <string>

#include "clients/sim/core/rng.h"
#include "clients/sim/core/world.h"

// Building blocks for the hand-modelled outdoor and fly-roll scenes.
namespace semnav::sim::parts {

BoxShape Box(double x, double y, double length, double width, double height, double yaw = 0.0,
             double base_z = 0.0);
// A flat, drivable / flyable surface patch (road, river, lawn) 2 cm high.
Obstacle Surface(const std::string& kind, Rgb colour, double x0, double y0, double x1, double y1);
// A tree: trunk plus a canopy box from 2 m up, `height` tall overall.
void AddTree(World& world, double x, double y, double height);
// A findable object with an id "<label>_<n>".
void AddObject(World& world, const std::string& label, Rgb colour, const BoxShape& box,
               const std::string& room = "");
// True if the footprint keeps `gap` from every box already placed and stands outside every
// raised prism (buildings), so random placements do not overlap.
bool FreeSpot(const World& world, const BoxShape& box, double gap);

}  // namespace semnav::sim::parts
