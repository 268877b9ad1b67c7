// The VLM-quality sweep's plot (issue 15): SR and path ratio (over the exploration-only baseline,
// episodes both found) against the simulated VLM's recognition accuracy, as a PNG.
#pragma once

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "clients/sim/bench/mission_report.h"

namespace semnav::sim::bench {

// `title` goes above the axes. INVALID_ARGUMENT for no points; INTERNAL when the PNG cannot be
// written.
absl::Status WriteVlmSweepPlot(const std::vector<SweepPoint>& points, const std::string& title,
                               const std::string& png_path);

}  // namespace semnav::sim::bench
