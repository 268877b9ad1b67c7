// What the gateway needs from a language model: the slow path's match_target call, the
// decomposition of complex instructions and text embeddings. Implemented over the model proxy
// (ModelProxyClient) and by scripted fakes in tests. Calls never block: they return at once and
// `done` runs later on another thread (seed 000, 3.5: the robot keeps exploring while the model
// thinks), never inside the call itself.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "services/reasoning/core/slow_answer.h"
#include "services/reasoning/core/subgoal_json.h"

namespace semnav::reasoning {

// Who a call is for (the proxy accounts usage per robot and task).
struct ModelCaller {
  std::string robot_id;
  std::string task_id;
  // When set, the model writes the latency it reports for the call (the proxy's response
  // `latency`) here before `done` runs: simulated-clock robots get the answer only once their
  // simulated time has covered it (docs/simulation.md, "Time").
  std::shared_ptr<absl::Duration> reported_latency = nullptr;
};

// A free-text question, with one PNG image for the vision model when `png` is not empty.
struct ModelQuestion {
  std::string prompt;
  std::string png;  // PNG file bytes; empty = text only
};

class LanguageModel {
 public:
  using AnswerDone = std::function<void(absl::StatusOr<std::string> answer)>;
  using EmbeddingDone = std::function<void(absl::StatusOr<std::vector<float>> embedding)>;

  virtual ~LanguageModel() = default;
  // The match_target request; `done` gets the answer object as JSON text (with "offline": true
  // when the proxy's commonsense prior answered) or the call's error.
  virtual void MatchTarget(const ModelCaller& caller, const ResolveRequest& request,
                           AnswerDone done) = 0;
  // The decompose request; `done` gets the {"subgoals": [...]} answer as JSON text or the call's
  // error (the proxy's offline backend answers it by rules; when it fails, the gateway's rules are
  // kept).
  virtual void Decompose(const ModelCaller& caller, const DecomposeRequest& request,
                         AnswerDone done) = 0;
  // A free-text answer (the EROI search's VLM and region-score prompts).
  virtual void Ask(const ModelCaller& caller, const ModelQuestion& question, AnswerDone done) = 0;
  // The text embedding of `text`; UNAVAILABLE while the proxy offers no embedding backend.
  virtual void EmbedText(const ModelCaller& caller, const std::string& text,
                         EmbeddingDone done) = 0;
  // Ends pending calls (their `done` runs with CANCELLED); returns once no `done` runs or will
  // run. Idempotent.
  virtual void Stop() = 0;
};

}  // namespace semnav::reasoning
