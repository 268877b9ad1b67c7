// Instruction -> first robot command over loopback gRPC: real semnav-mapping (fed with synthetic
// frames of the standard room with a clock on the far wall), real semnav-planning on mapping's live
// map, semnav-gateway using both, a robot session behind the table, and repeated "go to the
// clock" submissions resolved by the fast path; every NAVIGATE carries a path planned round the
// table.
#pragma once

#include "absl/status/statusor.h"

namespace semnav::reasoning {

struct LoopbackLatency {
  double p50_ms = 0.0;
  double p99_ms = 0.0;
  int samples = 0;
  int planned = 0;  // samples whose NAVIGATE carried a planned path
};

// `with_model_proxy`: the gateway also has the real semnav-model-proxy (offline default chain)
// configured, so each task makes its model calls (the text embedding) while it starts.
absl::StatusOr<LoopbackLatency> MeasureInstructionToCommand(int samples, bool with_model_proxy);

}  // namespace semnav::reasoning
