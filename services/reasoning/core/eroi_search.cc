#include "services/reasoning/core/eroi_search.h"

#include <algorithm>

#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"
#include "services/reasoning/core/search_prompts.h"
#include "services/reasoning/core/vlm_answer.h"

namespace semnav::reasoning {

absl::Status ValidateSearchRules(const EroiSearchConfig& config) {
  if (absl::Status s = CheckRange(config.inspect_distance_m, "inspect_distance_m", 0.0, 50.0);
      !s.ok())
    return s;
  if (absl::Status s = CheckRange(config.sighting_namings, "sighting_namings", 1, 10); !s.ok())
    return s;
  return CheckRange(config.failed_clues_to_geometric, "failed_clues_to_geometric", 0, 1000);
}

absl::StatusOr<EroiSearch> EroiSearch::Create(std::string target, const EroiSearchConfig& config) {
  if (target.empty()) return InvalidField("target", "is required for the EROI search");
  if (absl::Status s = ValidateSearchRules(config); !s.ok()) return s;
  absl::StatusOr<EroiGrid> grid = EroiGrid::Create(config.grid);
  if (!grid.ok()) return grid.status();
  return EroiSearch(std::move(target), *std::move(grid), config);
}

EroiSearch::EroiSearch(std::string target, EroiGrid grid, const EroiSearchConfig& config)
    : target_(std::move(target)),
      grid_(std::make_unique<const EroiGrid>(std::move(grid))),
      evidence_radius_m_(config.evidence_radius_m > 0.0 ? config.evidence_radius_m
                                                        : config.grid.delta),
      mapping_config_(config.mapping),
      regions_(grid_.get(), config.regions),
      values_(grid_->size()),
      evidence_once_per_code_(config.evidence_once_per_code),
      inspect_distance_m_(config.inspect_distance_m),
      sighting_namings_(config.sighting_namings),
      failed_clues_to_geometric_(config.failed_clues_to_geometric) {}

EroiObservation EroiSearch::Annotate(const Eigen::Vector3d& position,
                                     const Eigen::Quaterniond& orientation,
                                     const PinholeCamera& camera, cv::Mat& image) const {
  const InverseMapper mapper(grid_.get(), mapping_config_);
  EroiObservation observation;
  observation.labels = InverseMapper::Cull(mapper.Project(position, orientation, camera));
  mapper.Draw(observation.labels, image);
  observation.prompt = BuildSearchPrompt(target_);
  return observation;
}

int EroiSearch::NewCodes(const EroiObservation& observation) const {
  return static_cast<int>(
      std::count_if(observation.labels.begin(), observation.labels.end(),
                    [&](const CodeLabel& label) { return !asked_codes_.contains(label.code); }));
}

void EroiSearch::OnAsked(const EroiObservation& observation) {
  for (const CodeLabel& label : observation.labels) asked_codes_.insert(label.code);
}

bool EroiSearch::Corroborated(const Eigen::Vector3d& centre) {
  if (sighting_namings_ <= 1) return true;
  // An answer can list many pairs: keep the count check linear in a bounded record.
  constexpr size_t kMaxNamings = 4096;
  if (namings_.size() >= kMaxNamings) namings_.erase(namings_.begin());
  const double near_m = 2.0 * grid_->spec().delta;
  const int earlier =
      static_cast<int>(std::count_if(namings_.begin(), namings_.end(), [&](const Naming& naming) {
        return naming.answer != answers_ && (naming.centre - centre).head<2>().norm() <= near_m;
      }));
  namings_.push_back({centre, answers_});
  return earlier + 1 >= sighting_namings_;
}

EroiEvidence EroiSearch::OnVlmAnswer(std::string_view answer) {
  EroiEvidence evidence;
  ++answers_;
  for (const CodeDescription& pair : ParseCodeDescriptions(answer)) {
    absl::StatusOr<Eigen::Vector3d> centre = grid_->Decode(pair.code);
    if (!centre.ok()) continue;  // a code the VLM invented or misread
    ++evidence.codes_used;
    if (!evidence_once_per_code_ || evidenced_codes_.insert(pair.code).second) {
      values_.ApplyVlmEvidence(grid_->Neighbourhood(*centre, evidence_radius_m_));
      const Eigen::Vector2d column = centre->head<2>();
      if (std::find(open_clues_.begin(), open_clues_.end(), column) == open_clues_.end())
        open_clues_.push_back(column);
    }
    if (DescriptionNamesTarget(pair.description, target_) && Corroborated(*centre) &&
        std::find(sightings_.begin(), sightings_.end(), *centre) == sightings_.end()) {
      sightings_.push_back(*centre);
      ++evidence.sightings;
    }
    absl::StatusOr<std::optional<RegionDue>> due = regions_.Add(*centre, pair.description);
    if (due.ok() && due->has_value()) evidence.due.push_back(**due);
  }
  return evidence;
}

std::string EroiSearch::RegionPrompt(const RegionDue& region) const {
  return BuildRegionScorePrompt(target_, region.descriptions);
}

absl::Status EroiSearch::OnRegionAnswer(const RegionDue& region, std::string_view answer) {
  absl::StatusOr<int> score = ParseRegionScore(answer);
  if (!score.ok()) return score.status();
  values_.ApplyRegionScore(region.erois, *score);
  return absl::OkStatus();
}

void EroiSearch::OnRobotAt(const Eigen::Vector3d& position) {
  // A clue raised the EROIs within r of it; from inspect_distance_m beyond those the detector
  // would have seen the target there.
  const double reach_m = evidence_radius_m_ + inspect_distance_m_;
  const auto near = [&](const Eigen::Vector2d& clue) {
    return (clue - position.head<2>()).norm() <= reach_m;
  };
  const auto reached = std::remove_if(open_clues_.begin(), open_clues_.end(), near);
  failed_clues_ += static_cast<int>(open_clues_.end() - reached);
  open_clues_.erase(reached, open_clues_.end());
}

bool EroiSearch::geometric() const {
  return failed_clues_to_geometric_ > 0 && failed_clues_ >= failed_clues_to_geometric_;
}

std::vector<double> EroiSearch::PlanarValues() const {
  const EroiGridSpec& spec = grid_->spec();
  const std::size_t columns = static_cast<std::size_t>((spec.nx + 1) * (spec.ny + 1));
  if (geometric()) return std::vector<double>(columns, values_.prior());
  std::vector<double> planar(columns, 0.0);
  for (int flat = 0; flat < grid_->size(); ++flat) {
    const EroiIndex index = grid_->Unflatten(flat);
    double& column = planar[static_cast<std::size_t>(index.j * (spec.nx + 1) + index.i)];
    column = std::max(column, values_.value(flat));
  }
  return planar;
}

Eigen::Vector2d EroiSearch::WindowMin() const {
  return grid_->spec().min.head<2>() - Eigen::Vector2d::Constant(grid_->spec().delta / 2.0);
}

Eigen::Vector2d EroiSearch::WindowMax() const {
  const EroiGridSpec& spec = grid_->spec();
  return WindowMin() + spec.delta * Eigen::Vector2d(spec.nx + 1, spec.ny + 1);
}

}  // namespace semnav::reasoning
