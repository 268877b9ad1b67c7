#include "services/relocalization/server/service_config.h"

#include <vector>

namespace semnav::relocalization {
namespace {

void ReadObjectPoints(ConfigReader r, ObjectPointParams& p) {
  r.Read("nms_kernel", &p.nms_kernel)
      .Read("top_k", &p.top_k)
      .Read("box_iou_threshold", &p.box_iou_threshold);
  r.Check(p.nms_kernel >= 0, "nms_kernel", "must be >= 0");
  r.Check(p.top_k > 0, "top_k", "must be > 0");
  r.Check(p.box_iou_threshold > 0.0 && p.box_iou_threshold <= 1.0, "box_iou_threshold",
          "must be in (0, 1]");
}

void ReadDetector(ConfigReader r, OnnxHeadsConfig& d) {
  std::vector<double> mean = {d.mean_r, d.mean_g, d.mean_b};
  r.Read("model_path", &d.model_path)
      .Read("input_width", &d.input_width)
      .Read("input_height", &d.input_height)
      .Read("pixel_scale", &d.pixel_scale)
      .Read("mean_rgb", &mean)
      .Read("swap_rb", &d.swap_rb)
      .Read("heatmap_output", &d.heatmap_output)
      .Read("offset_output", &d.offset_output)
      .Read("size_output", &d.size_output)
      .Read("feature_output", &d.feature_output);
  r.Check(mean.size() == 3, "mean_rgb", "must have 3 values");
  if (mean.size() == 3) {
    d.mean_r = mean[0];
    d.mean_g = mean[1];
    d.mean_b = mean[2];
  }
  r.Check(d.input_width > 0 && d.input_height > 0, "input_width",
          "input_width/input_height must be > 0");
}

void ReadMatching(ConfigReader r, MatchParams& m) {
  SimilarityParams& s = m.similarity;
  r.Read("alpha", &s.alpha).Read("beta", &s.beta).Read("gamma", &s.gamma);
  r.Read("pos_threshold", &s.pos_threshold)
      .Read("scale_threshold", &s.scale_threshold)
      .Read("desc_threshold", &s.desc_threshold)
      .Read("pos_sigma_m", &s.pos_sigma_m)
      .Read("pos_sigma_per_scale", &s.pos_sigma_per_scale);
  r.Read("neighbourhood_size", &m.neighbourhood_size)
      .Read("max_candidates", &m.max_candidates)
      .Read("retrieval_labels", &m.retrieval_labels)
      .Read("min_neighbour_matches", &m.min_neighbour_matches)
      .Read("early_stop_matches", &m.early_stop_matches)
      .Read("rematch_radius_m", &m.rematch_radius_m);
  r.Check(s.alpha >= 0 && s.beta >= 0 && s.gamma >= 0 && s.alpha + s.beta + s.gamma > 0, "alpha",
          "alpha, beta, gamma must be >= 0 and not all 0");
  r.Check(s.pos_sigma_m > 0, "pos_sigma_m", "must be > 0");
  r.Check(s.pos_sigma_per_scale >= 0 && s.pos_sigma_per_scale <= 2, "pos_sigma_per_scale",
          "must be in [0, 2]");
  r.Check(m.max_candidates > 0, "max_candidates", "must be > 0");
  r.Check(m.retrieval_labels > 0, "retrieval_labels", "must be > 0");
  r.Check(m.early_stop_matches >= 3, "early_stop_matches", "must be >= 3");
  r.Check(m.rematch_radius_m > 0, "rematch_radius_m", "must be > 0");
}

void ReadPose(ConfigReader r, PoseParams& p) {
  r.Read("outlier_distance_m", &p.outlier_distance_m)
      .Read("max_reference_pairs", &p.max_reference_pairs)
      .Read("min_inliers", &p.min_inliers)
      .Read("lm_max_iterations", &p.lm_max_iterations)
      .Read("lm_initial_lambda", &p.lm_initial_lambda)
      .Read("lm_min_step", &p.lm_min_step);
  r.Check(p.outlier_distance_m > 0, "outlier_distance_m", "must be > 0");
  r.Check(p.min_inliers >= 3, "min_inliers", "must be >= 3");
  r.Check(p.lm_max_iterations > 0, "lm_max_iterations", "must be > 0");
  r.Check(p.lm_initial_lambda > 0, "lm_initial_lambda", "must be > 0");
}

void ReadReliability(ConfigReader r, RelocalizationParams& p) {
  r.Read("translation_m", &p.reliable_translation_m)
      .Read("rotation_deg", &p.reliable_rotation_deg)
      .Read("min_inliers", &p.reliable_min_inliers)
      .Read("max_rms_m", &p.reliable_max_rms_m)
      .Read("min_spread_m", &p.reliable_min_spread_m);
  r.Check(p.reliable_translation_m > 0, "translation_m", "must be > 0");
  r.Check(p.reliable_rotation_deg > 0, "rotation_deg", "must be > 0");
  r.Check(p.reliable_max_rms_m >= 0, "max_rms_m", "must be >= 0 (0 = off)");
  r.Check(p.reliable_min_spread_m >= 0, "min_spread_m", "must be >= 0 (0 = off)");
}

void ReadLookalikeTwins(ConfigReader r, TwinParams& t) {
  r.Read("radius_m", &t.radius_m)
      .Read("min_cosine", &t.min_cosine)
      .Read("pose_tolerance_m", &t.pose_tolerance_m)
      .Read("pose_tolerance_deg", &t.pose_tolerance_deg);
  r.Check(t.radius_m >= 0, "radius_m", "must be >= 0 (0 = off)");
  r.Check(t.min_cosine > 0 && t.min_cosine <= 1, "min_cosine", "must be in (0, 1]");
  r.Check(t.pose_tolerance_m >= 0, "pose_tolerance_m", "must be >= 0");
  r.Check(t.pose_tolerance_deg >= 0, "pose_tolerance_deg", "must be >= 0");
}

}  // namespace

absl::StatusOr<ServiceConfig> ServiceConfig::FromYaml(ConfigReader& section) {
  ServiceConfig c;
  section.Read("storage_dir", &c.storage_dir)
      .Read("idempotency_cache", &c.idempotency_cache)
      .Read("rematch_rounds", &c.relocalization.rematch_rounds)
      .Read("max_hypotheses", &c.relocalization.max_hypotheses)
      .Read("final_residual_gate_m", &c.relocalization.final_residual_gate_m);
  section.Check(c.relocalization.rematch_rounds >= 1, "rematch_rounds", "must be >= 1");
  section.Check(c.relocalization.max_hypotheses >= 1, "max_hypotheses", "must be >= 1");
  section.Check(c.relocalization.final_residual_gate_m >= 0, "final_residual_gate_m",
                "must be >= 0 (0 = off)");
  ReadObjectPoints(section.Child("object_points"), c.object_points);
  ReadDetector(section.Child("detector"), c.detector);
  ConfigReader merge = section.Child("merge");
  merge.Read("radius_m", &c.merge.radius_m)
      .Read("min_descriptor_similarity", &c.merge.min_descriptor_similarity);
  merge.Check(c.merge.radius_m >= 0, "radius_m", "must be >= 0");
  ReadMatching(section.Child("matching"), c.relocalization.match);
  ReadPose(section.Child("pose"), c.relocalization.pose);
  ReadReliability(section.Child("reliability"), c.relocalization);
  ReadLookalikeTwins(section.Child("lookalike_twins"), c.relocalization.twin);
  if (absl::Status s = section.Finish(); !s.ok()) return s;
  return c;
}

}  // namespace semnav::relocalization
