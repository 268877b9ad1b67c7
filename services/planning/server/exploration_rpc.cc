#include "services/planning/server/exploration_rpc.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/value_checks.h"
#include "services/planning/core/exploration_goal.h"
#include "services/planning/core/look_goal.h"
#include "services/planning/server/request_checks.h"

namespace semnav::planning {
namespace {

namespace pb = semnav::planning::v1;
using semnav::common::v1::GridMap;

// A frontier needs at least this many cells; more than a whole grid holds finds none.
constexpr uint32_t kMaxMinCells = uint32_t{1} << 26;

// One request as the core's grid and query.
struct FrontierView {
  GridFrame frame;
  ExplorationGrid grid;
  ExplorationQuery query;
};

Point2 ToPoint(const semnav::common::v1::Pose2D& p) { return {p.x(), p.y()}; }

std::vector<Point2> VisitedOf(const pb::SemanticContext& semantics) {
  std::vector<Point2> visited;
  for (const auto& v : semantics.visited()) visited.push_back(ToPoint(v));
  return visited;
}

std::vector<ScoredObject> ObjectsOf(const pb::SemanticContext& semantics) {
  std::vector<ScoredObject> objects;
  for (const auto& o : semantics.objects()) {
    objects.push_back({ToPoint(o.position()), o.relevance(), o.relation(), o.cooccurrence()});
  }
  return objects;
}

void SetScore(const FrontierScore& s, pb::FrontierScore* score) {
  score->set_distance(s.distance);
  score->set_novelty(s.novelty);
  score->set_language(s.language);
  score->set_grounding(s.grounding);
  score->set_total(s.total);
}

absl::Status Invalid(const std::string& field, absl::string_view message) {
  return FieldError(absl::StatusCode::kInvalidArgument, field, absl::StrCat(field, " ", message));
}

// The config weights with the request's overrides; INVALID_ARGUMENT names a
// weight that is negative or not finite.
absl::StatusOr<FrontierScoreConfig> WeightsOf(const pb::FrontierScoreWeights& weights,
                                              FrontierScoreConfig config) {
  const struct {
    bool set;
    double value;
    const char* name;
    double* target;
  } overrides[] = {
      {weights.has_distance(), weights.distance(), "distance", &config.distance_weight},
      {weights.has_novelty(), weights.novelty(), "novelty", &config.novelty_weight},
      {weights.has_language(), weights.language(), "language", &config.language_weight},
      {weights.has_grounding(), weights.grounding(), "grounding", &config.grounding_weight},
  };
  for (const auto& o : overrides) {
    if (!o.set) continue;
    if (!std::isfinite(o.value) || o.value < 0 || o.value > kMaxScore) {
      return Invalid(absl::StrCat("weights.", o.name),
                     absl::StrCat("must be a finite value in [0, ", kMaxScore, "]"));
    }
    *o.target = o.value;
  }
  return config;
}

// Goals the caller could not reach; a goal within `radius` of one is skipped.
struct Exclusions {
  std::vector<Point2> goals;
  double radius = 1.0;
  bool Covers(const Point2& p) const {
    for (const Point2& g : goals) {
      if (std::hypot(p.x - g.x, p.y - g.y) <= radius) return true;
    }
    return false;
  }
};

Exclusions ReadExclusions(const pb::SelectExplorationGoalRequest& request) {
  Exclusions out;
  for (const auto& g : request.excluded_goals()) out.goals.push_back(ToPoint(g));
  if (request.excluded_radius_m() > 0) out.radius = request.excluded_radius_m();
  return out;
}

// The operator's search area; unset = no bound.
struct SearchBounds {
  std::optional<pb::SearchArea> area;
  bool Outside(const Point2& p) const {
    return area.has_value() && (p.x < area->min_x() || p.x > area->max_x() || p.y < area->min_y() ||
                                p.y > area->max_y());
  }
};

absl::StatusOr<SearchBounds> ReadSearchBounds(const pb::SelectExplorationGoalRequest& request) {
  if (!request.has_search_area()) return SearchBounds{};
  const pb::SearchArea& a = request.search_area();
  const struct {
    double value;
    const char* field;
  } corners[] = {{a.min_x(), "search_area.min_x"},
                 {a.min_y(), "search_area.min_y"},
                 {a.max_x(), "search_area.max_x"},
                 {a.max_y(), "search_area.max_y"}};
  for (const auto& corner : corners) {
    if (absl::Status s = CheckMagnitude(corner.value, corner.field, kMaxCoordinateM); !s.ok()) {
      return s;
    }
  }
  if (a.min_x() >= a.max_x() || a.min_y() >= a.max_y()) {
    return Invalid("search_area", "min_x must be < max_x and min_y < max_y");
  }
  return SearchBounds{a};
}

// Frontier cells a goal must not be chosen from: near an excluded goal or outside the area.
struct GoalFilter {
  Exclusions exclusions;
  SearchBounds bounds;
  bool Drops(const Point2& p) const { return exclusions.Covers(p) || bounds.Outside(p); }
  bool empty() const { return exclusions.goals.empty() && !bounds.area.has_value(); }
};

// Footprint radius and clearance limit, metres (a robot wider than 10 m is no ground robot).
constexpr double kMaxFootprintM = 5.0;

// A ground robot's footprint in cells: reached within twice the radius plus one cell, a start
// the inflation blocks or boxes in left through GridPlanner's snap radius.
FootprintReachConfig FootprintOf(const pb::SelectExplorationGoalRequest& request,
                                 const PlanningConfig& config, double resolution) {
  const double radius_cells = request.robot_radius_m() / resolution;
  return {.radius_cells = radius_cells,
          .reach_cells = 2.0 * radius_cells + 1.0,
          .start_snap_cells = config.grid_planner.start_snap_radius_m / resolution,
          .clear_radius_cells = (request.robot_radius_m() + request.clearance_m()) / resolution};
}

// The checked request pieces as the core's grid and query.
absl::StatusOr<FrontierView> BuildView(const GridMap& grid, const std::string& field,
                                       const semnav::common::v1::Pose2D& robot, uint32_t min_cells,
                                       const std::string& min_cells_field,
                                       const pb::SemanticContext& semantics,
                                       const PlanningConfig& config, const GoalFilter& filter = {},
                                       bool take_in_robot = true) {
  FrontierView view;
  if (absl::Status s = CheckSemantics(semantics, "semantics"); !s.ok()) return s;
  if (min_cells > kMaxMinCells) {
    return InvalidField(min_cells_field, absl::StrCat("must be at most ", kMaxMinCells));
  }
  absl::StatusOr<GridFrame> frame = ReadGridFrame(grid, field);
  if (!frame.ok()) return frame.status();
  view.frame = *frame;
  absl::StatusOr<Cell> cell =
      take_in_robot ? view.frame.ToCellAnywhere(robot, "robot") : view.frame.ToCell(robot, "robot");
  if (!cell.ok()) return cell.status();
  view.query.robot = *cell;
  view.query.robot_yaw_rad = robot.yaw();
  view.query.min_frontier_cells =
      min_cells > 0 ? static_cast<int>(min_cells) : config.exploration.min_frontier_cells;
  view.query.objects = ObjectsOf(semantics);
  view.query.visited = VisitedOf(semantics);
  if (!filter.empty()) {
    view.query.excluded = [filter](Point2 p) { return filter.Drops(p); };
  }
  if (filter.bounds.area.has_value()) {
    view.query.outside_area = [bounds = filter.bounds](Point2 p) { return bounds.Outside(p); };
  }
  view.grid.resolution_m = frame->resolution;
  view.grid.origin_x = frame->origin_x;
  view.grid.origin_y = frame->origin_y;
  absl::StatusOr<CellGrid<uint8_t>> explored = ToExplored(grid, field);
  if (!explored.ok()) return explored.status();
  view.grid.explored = *std::move(explored);
  absl::StatusOr<PassabilityGrid> free =
      ToPassability(grid, {config.occupied_percent, false}, field);
  if (!free.ok()) return free.status();
  view.grid.free = *std::move(free);
  // A robot just outside the map it drew (its own cell unseen yet) is taken in, as PlanPath's
  // 2D planners take in such a start; the frame follows the grown grid. Not for EROI_UTILITY:
  // the caller's EROI values are counted over the grid as mapping sent it.
  if (!take_in_robot) return view;
  absl::StatusOr<Padding> pad =
      TakeInRobot(view.grid, view.query, config.grid_planner.max_start_outside_m);
  if (!pad.ok()) return pad.status();
  view.frame.origin_x = view.grid.origin_x;
  view.frame.origin_y = view.grid.origin_y;
  view.frame.width += pad->left + pad->right;
  view.frame.height += pad->bottom + pad->top;
  return view;
}

pb::ExplorationStrategy ToProto(ExplorationStrategy strategy) {
  switch (strategy) {
    case ExplorationStrategy::kCoverageMax:
      return pb::EXPLORATION_STRATEGY_COVERAGE_MAX;
    case ExplorationStrategy::kSemanticFrontier:
      return pb::EXPLORATION_STRATEGY_SEMANTIC_FRONTIER;
    case ExplorationStrategy::kEroiUtility:
      return pb::EXPLORATION_STRATEGY_EROI_UTILITY;
    case ExplorationStrategy::kNearestFrontier:
      break;
  }
  return pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER;
}

ExplorationPlatform FromProto(pb::ExplorationPlatform platform) {
  switch (platform) {
    case pb::EXPLORATION_PLATFORM_GROUND:
      return ExplorationPlatform::kGround;
    case pb::EXPLORATION_PLATFORM_AERIAL:
      return ExplorationPlatform::kAerial;
    default:
      return ExplorationPlatform::kUnspecified;
  }
}

ExplorationStrategy FromProto(pb::ExplorationStrategy strategy) {
  switch (strategy) {
    case pb::EXPLORATION_STRATEGY_COVERAGE_MAX:
      return ExplorationStrategy::kCoverageMax;
    case pb::EXPLORATION_STRATEGY_SEMANTIC_FRONTIER:
      return ExplorationStrategy::kSemanticFrontier;
    case pb::EXPLORATION_STRATEGY_EROI_UTILITY:
      return ExplorationStrategy::kEroiUtility;
    default:  // UNSPECIFIED = nearest frontier
      return ExplorationStrategy::kNearestFrontier;
  }
}

// SelectExplorationGoal with look_at: where to look at a sighting from (look_goal.h).
absl::Status LookOn(const GridMap& grid, const std::string& field,
                    const pb::SelectExplorationGoalRequest& request, const PlanningConfig& config,
                    ExplorationStrategy strategy, pb::SelectExplorationGoalResponse* response) {
  absl::StatusOr<FrontierView> view =
      BuildView(grid, field, request.robot(), 0, "min_frontier_cells", request.semantics(), config);
  if (!view.ok()) return view.status();
  const LookGoalConfig look{
      .distance_m =
          request.look_distance_m() > 0.0 ? request.look_distance_m() : LookGoalConfig{}.distance_m,
      .clearance_m = std::max(config.exploration.look_clearance_m,
                              request.robot_radius_m() + request.clearance_m())};
  const Point2 robot = ToPoint(request.robot());
  const Point2 goal = LookGoal(view->grid, robot, ToPoint(request.look_at()), look);
  response->set_strategy(ToProto(strategy));
  response->set_map_revision(grid.revision());
  response->mutable_goal()->set_x(goal.x);
  response->mutable_goal()->set_y(goal.y);
  response->set_score(std::hypot(goal.x - robot.x, goal.y - robot.y));
  return absl::OkStatus();
}

}  // namespace

absl::Status ExtractFrontiersOn(const GridMap& grid, const std::string& field,
                                const pb::ExtractFrontiersRequest& request,
                                const PlanningConfig& config,
                                pb::ExtractFrontiersResponse* response) {
  absl::StatusOr<FrontierView> view = BuildView(grid, field, request.robot(), request.min_cells(),
                                                "min_cells", request.semantics(), config);
  if (!view.ok()) return view.status();
  const FrontierSet set = CollectFrontiers(view->grid, view->query, config.exploration.score);
  for (size_t i = 0; i < set.frontiers.size(); ++i) {
    pb::Frontier* f = response->add_frontiers();
    f->mutable_centroid()->set_x(set.candidates[i].centroid.x);
    f->mutable_centroid()->set_y(set.candidates[i].centroid.y);
    *f->mutable_anchor() = view->frame.ToPose(set.frontiers[i].anchor);
    f->set_size_cells(static_cast<uint32_t>(set.frontiers[i].cells.size()));
    f->set_path_distance_m(set.candidates[i].path_distance_m);
    SetScore(set.scores[i], f->mutable_score());
  }
  response->set_map_revision(grid.revision());
  return absl::OkStatus();
}

absl::Status ScoreFrontiersOn(const pb::ScoreFrontiersRequest& request,
                              const PlanningConfig& config, pb::ScoreFrontiersResponse* response) {
  absl::StatusOr<FrontierScoreConfig> weights =
      WeightsOf(request.weights(), config.exploration.score);
  if (!weights.ok()) return weights.status();
  if (absl::Status s = CheckPose2D(request.robot(), "robot"); !s.ok()) return s;
  if (absl::Status s = CheckSemantics(request.semantics(), "semantics"); !s.ok()) return s;
  if (absl::Status s = CheckCount(request.frontiers_size(), "frontiers", kMaxListItems); !s.ok()) {
    return s;
  }
  std::vector<FrontierCandidate> candidates;
  for (int i = 0; i < request.frontiers_size(); ++i) {
    const pb::Frontier& f = request.frontiers(i);
    const std::string at = absl::StrCat("frontiers[", i, "]");
    if (absl::Status s = CheckPose2D(f.centroid(), at + ".centroid"); !s.ok()) return s;
    if (absl::Status s = CheckPose2D(f.anchor(), at + ".anchor"); !s.ok()) return s;
    if (!std::isfinite(f.path_distance_m()) || std::abs(f.path_distance_m()) > kMaxPathM) {
      return Invalid(at + ".path_distance_m", absl::StrCat("must be finite and within +-",
                                                           kMaxPathM, " (< 0 = unreachable)"));
    }
    // A previous answer's score may be sent back; it is recomputed, but must still be a number.
    const pb::FrontierScore& score = f.score();
    for (const auto& [value, name] :
         {std::pair{score.distance(), "distance"}, std::pair{score.novelty(), "novelty"},
          std::pair{score.language(), "language"}, std::pair{score.grounding(), "grounding"},
          std::pair{score.total(), "total"}}) {
      if (absl::Status s = CheckScore(value, absl::StrCat(at, ".score.", name)); !s.ok()) return s;
    }
    candidates.push_back({ToPoint(f.centroid()), f.path_distance_m()});
  }
  const std::vector<FrontierScore> scores =
      ScoreFrontiers(candidates, ToPoint(request.robot()), VisitedOf(request.semantics()),
                     ObjectsOf(request.semantics()), *weights);
  int best = -1;
  for (size_t i = 0; i < scores.size(); ++i) {
    SetScore(scores[i], response->add_scores());
    if (candidates[i].path_distance_m < 0) continue;
    if (best < 0 || scores[i].total > scores[best].total) best = static_cast<int>(i);
  }
  response->set_best_index(best);
  return absl::OkStatus();
}

absl::Status SelectGoalOn(const GridMap& grid, const std::string& field,
                          const pb::SelectExplorationGoalRequest& request,
                          const PlanningConfig& config,
                          pb::SelectExplorationGoalResponse* response) {
  if (absl::Status s =
          CheckRange(request.excluded_radius_m(), "excluded_radius_m", 0.0, 2 * kMaxCoordinateM);
      !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckCount(request.excluded_goals_size(), "excluded_goals", kMaxListItems);
      !s.ok()) {
    return s;
  }
  for (int i = 0; i < request.excluded_goals_size(); ++i) {
    if (absl::Status s =
            CheckPose2D(request.excluded_goals(i), absl::StrCat("excluded_goals[", i, "]"));
        !s.ok()) {
      return s;
    }
  }
  if (absl::Status s =
          CheckCount(request.eroi_semantic_values_size(), "eroi_semantic_values", kMaxListItems);
      !s.ok()) {
    return s;
  }
  for (int i = 0; i < request.eroi_semantic_values_size(); ++i) {
    if (absl::Status s = CheckScore(request.eroi_semantic_values(i),
                                    absl::StrCat("eroi_semantic_values[", i, "]"));
        !s.ok()) {
      return s;
    }
  }
  if (!pb::ExplorationStrategy_IsValid(request.strategy())) {
    return InvalidField("strategy", "unknown exploration strategy");
  }
  if (!pb::ExplorationPlatform_IsValid(request.platform())) {
    return InvalidField("platform", "unknown exploration platform");
  }
  if (absl::Status s = CheckRange(request.eroi_size_m(), "eroi_size_m", 0.0, 100.0); !s.ok()) {
    return s;
  }
  if (request.eroi_size_m() > 0.0 && request.eroi_size_m() < 0.1) {
    return InvalidField("eroi_size_m", "must be 0 (the configured edge) or in [0.1, 100] m");
  }
  if (request.has_keep_goal()) {
    if (absl::Status s = CheckPose2D(request.keep_goal(), "keep_goal"); !s.ok()) return s;
  }
  if (absl::Status s = CheckRange(request.keep_radius_m(), "keep_radius_m", 0.0, 50.0); !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckRange(request.robot_radius_m(), "robot_radius_m", 0.0, kMaxFootprintM);
      !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckRange(request.clearance_m(), "clearance_m", 0.0, kMaxFootprintM);
      !s.ok()) {
    return s;
  }
  if (request.has_look_at()) {
    if (absl::Status s = CheckPose2D(request.look_at(), "look_at"); !s.ok()) return s;
  }
  if (absl::Status s = CheckRange(request.look_distance_m(), "look_distance_m", 0.0, 50.0);
      !s.ok()) {
    return s;
  }
  absl::StatusOr<SearchBounds> bounds = ReadSearchBounds(request);
  if (!bounds.ok()) return bounds.status();
  const GoalFilter filter{ReadExclusions(request), *bounds};
  const ExplorationStrategy strategy = FromProto(request.strategy());
  if (request.has_look_at()) return LookOn(grid, field, request, config, strategy, response);
  absl::StatusOr<FrontierView> view =
      BuildView(grid, field, request.robot(), request.min_frontier_cells(), "min_frontier_cells",
                request.semantics(), config, filter, strategy != ExplorationStrategy::kEroiUtility);
  if (!view.ok()) return view.status();
  view->query.platform = FromProto(request.platform());
  if (request.has_keep_goal()) view->query.keep_goal = ToPoint(request.keep_goal());
  if (request.keep_radius_m() > 0.0) view->query.keep_radius_m = request.keep_radius_m();
  if (request.robot_radius_m() > 0.0) {
    view->grid.footprint = FootprintOf(request, config, view->frame.resolution);
  }
  view->query.eroi_values.assign(request.eroi_semantic_values().begin(),
                                 request.eroi_semantic_values().end());
  ExplorationGoalConfig goal_config = config.exploration.GoalConfig(view->frame.resolution);
  if (request.eroi_size_m() > 0.0) {  // the caller's EROI grid (its values are per these EROIs)
    goal_config.eroi.eroi_size_cells =
        std::max(1, static_cast<int>(std::lround(request.eroi_size_m() / view->frame.resolution)));
  }
  absl::StatusOr<ExplorationChoice> choice =
      SelectExplorationGoal(view->grid, view->query, strategy, goal_config);
  if (!choice.ok()) return choice.status();
  response->set_strategy(ToProto(strategy));
  response->set_map_revision(grid.revision());
  *response->mutable_goal() = view->frame.ToPose(choice->goal);
  if (strategy != ExplorationStrategy::kCoverageMax) response->set_score(choice->score);
  for (const Cell& c : choice->route) *response->add_route() = view->frame.ToPose(c);
  return absl::OkStatus();
}

}  // namespace semnav::planning
