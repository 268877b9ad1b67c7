#include "clients/sim/vlm/sim_vlm_config.h"

#include <algorithm>

#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::sim::vlm {

SimVlmErrors ErrorsAtAccuracy(double accuracy) {
  const SimVlmErrors defaults;
  const double scale = (1.0 - std::clamp(accuracy, 0.0, 1.0)) / defaults.miss_rate;
  return {std::min(1.0, defaults.miss_rate * scale), std::min(1.0, defaults.confusion_rate * scale),
          std::min(1.0, defaults.hallucination_rate * scale),
          std::min(1.0, defaults.code_off_by_one_rate * scale)};
}

absl::Status ValidateSimVlmConfig(const SimVlmConfig& config) {
  const SimVlmErrors& e = config.errors;
  for (const auto& [value, field] :
       {std::pair{e.miss_rate, "errors.miss_rate"},
        std::pair{e.confusion_rate, "errors.confusion_rate"},
        std::pair{e.hallucination_rate, "errors.hallucination_rate"},
        std::pair{e.code_off_by_one_rate, "errors.code_off_by_one_rate"},
        std::pair{config.max_changed_share, "max_changed_share"}}) {
    if (absl::Status s = CheckRange(value, field, 0.0, 1.0); !s.ok()) return s;
  }
  const SimVlmLatency& l = config.latency;
  for (const auto& [value, field] : {std::pair{l.vision_median_s, "latency.vision_median_s"},
                                     std::pair{l.text_median_s, "latency.text_median_s"},
                                     std::pair{l.embedding_median_s, "latency.embedding_median_s"},
                                     std::pair{l.max_s, "latency.max_s"}}) {
    if (absl::Status s = CheckRange(value, field, 1e-6, 600.0); !s.ok()) return s;
  }
  if (absl::Status s = CheckRange(l.sigma, "latency.sigma", 0.0, 3.0); !s.ok()) return s;
  if (config.min_pixels < 1) return InvalidField("min_pixels", "must be >= 1");
  if (absl::Status s = CheckRange(config.max_range_m, "max_range_m", 0.5, 1e4); !s.ok()) return s;
  if (absl::Status s = CheckRange(config.font_scale, "font_scale", 0.1, 5.0); !s.ok()) return s;
  if (absl::Status s = CheckRange(config.max_code_distance_px, "max_code_distance_px", 0.0, 1e5);
      !s.ok())
    return s;
  if (config.embedding_dim < 1 || config.embedding_dim > 4096)
    return InvalidField("embedding_dim", "must be 1..4096");
  if (absl::Status s = CheckRange(config.text_embedding_noise, "text_embedding_noise", 0.0, 10.0);
      !s.ok())
    return s;
  if (config.font_thickness < 1 || config.font_thickness > 5)
    return InvalidField("font_thickness", "must be 1..5");
  return absl::OkStatus();
}

}  // namespace semnav::sim::vlm
