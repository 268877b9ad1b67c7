#include "services/planning/bench/rrtstar_suite.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "services/planning/bench/timing.h"
#include "services/planning/core/jump_astar.h"
#include "services/planning/core/random_layered_map.h"

namespace semnav::planning::bench {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

struct PathFigures {
  double length_m = 0.0;
  double fly_m = 0.0;
  double energy_j = 0.0;
};

// Length and energy of a polyline in metres, sampled every quarter cell:
// a piece over an obstacle cell is flown (eq. 12), elsewhere rolled (eq. 10).
PathFigures Measure(const og::PathGeometric& path, const LayeredGrid& grid, double resolution,
                    const EnergyModel& energy) {
  PathFigures out;
  for (size_t i = 1; i < path.getStateCount(); ++i) {
    const auto* a = path.getState(i - 1)->as<ob::RealVectorStateSpace::StateType>();
    const auto* b = path.getState(i)->as<ob::RealVectorStateSpace::StateType>();
    const double dx = b->values[0] - a->values[0];
    const double dy = b->values[1] - a->values[1];
    const double length = std::hypot(dx, dy);
    const int steps = std::max(1, static_cast<int>(std::ceil(length / (resolution / 4))));
    for (int k = 0; k < steps; ++k) {
      const double t = (k + 0.5) / steps;
      const int cx = static_cast<int>((a->values[0] + t * dx) / resolution);
      const int cy = static_cast<int>((a->values[1] + t * dy) / resolution);
      const bool flying = grid.Contains(cx, cy) && grid.at(cx, cy) != 0;
      const double piece = length / steps;
      out.length_m += piece;
      if (flying) out.fly_m += piece;
      out.energy_j += piece * (flying ? energy.FlyingJPerM() : energy.rolling_j_per_m);
    }
  }
  return out;
}

}  // namespace

nlohmann::json RunRrtStarSuite(double seconds) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  const RandomLayeredMapSpec spec;
  const RandomLayeredMap map = MakeRandomLayeredMap(spec);
  const double res = spec.resolution_m;

  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0.0);
  bounds.setHigh(spec.size_m);
  space->setBounds(bounds);
  og::SimpleSetup setup(space);
  // Structure blocks; obstacle cells are valid (the robot may fly over them).
  setup.setStateValidityChecker([&](const ob::State* state) {
    const auto* v = state->as<ob::RealVectorStateSpace::StateType>();
    const int cx = static_cast<int>(v->values[0] / res);
    const int cy = static_cast<int>(v->values[1] / res);
    return map.grid.Contains(cx, cy) && map.grid.at(cx, cy) < kStructureValue;
  });
  // Check motions every half cell.
  space->setLongestValidSegmentFraction(0.5 * res / space->getMaximumExtent());
  ob::ScopedState<ob::RealVectorStateSpace> start(space);
  ob::ScopedState<ob::RealVectorStateSpace> goal(space);
  start[0] = (map.start.x + 0.5) * res;
  start[1] = (map.start.y + 0.5) * res;
  goal[0] = (map.goal.x + 0.5) * res;
  goal[1] = (map.goal.y + 0.5) * res;
  setup.setStartAndGoalStates(start, goal, res);
  setup.setPlanner(std::make_shared<og::RRTstar>(setup.getSpaceInformation()));
  setup.setup();
  const auto t0 = std::chrono::steady_clock::now();
  double first_solution_ms = -1.0;
  setup.getProblemDefinition()->setIntermediateSolutionCallback(
      [&](const ob::Planner*, const std::vector<const ob::State*>&, const ob::Cost&) {
        if (first_solution_ms < 0) {
          first_solution_ms =
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                  .count();
        }
      });
  const double solve_ms = TimeMs([&] { setup.solve(seconds); });
  nlohmann::json out;
  const EnergyModel energy;
  JumpAStarPlanner planner;
  MultiModalPath ja;
  const double ja_ms = TimeMs([&] { ja = *planner.Plan(map.grid, map.start, map.goal, {}); });
  std::printf("\nAnchor: OMPL RRT* (%.1f s budget) vs improved Jump A* (alpha = beta = 1)\n",
              seconds);
  std::printf("%-10s %10s %16s %10s %8s %10s\n", "planner", "time_ms", "first_sol_ms", "length_m",
              "fly_m", "energy_j");
  if (!setup.haveExactSolutionPath()) {
    std::printf("RRT* found no exact solution in %.1f s\n", seconds);
    out["rrtstar_ms"] = solve_ms;
    out["rrtstar_solved"] = false;
    return out;
  }
  const PathFigures rrt = Measure(setup.getSolutionPath(), map.grid, res, energy);
  std::printf("%-10s %10.1f %16.1f %10.2f %8.2f %10.0f\n", "RRT*", solve_ms, first_solution_ms,
              rrt.length_m, rrt.fly_m, rrt.energy_j);
  std::printf("%-10s %10.2f %16s %10.2f %8.2f %10.0f\n", "JumpA*", ja_ms, "-", ja.length_m,
              ja.fly_m, ja.energy_j);
  out["rrtstar_solved"] = true;
  out["rrtstar_ms"] = solve_ms;
  out["rrtstar_first_solution_ms"] = first_solution_ms;
  out["rrtstar_length_m"] = rrt.length_m;
  out["rrtstar_fly_m"] = rrt.fly_m;
  out["rrtstar_energy_j"] = rrt.energy_j;
  out["ja_length_m"] = ja.length_m;
  out["ja_energy_j"] = ja.energy_j;
  return out;
}

}  // namespace semnav::planning::bench
