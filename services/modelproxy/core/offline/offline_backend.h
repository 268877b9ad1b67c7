#pragma once
// The embedded backend used when there is no network or key: answers the structured tasks
// carried as a JSON text part of the last user message; marks every answer offline.
#include "services/common/place_prior/place_prior.h"
#include "services/modelproxy/core/backend.h"
#include "services/modelproxy/core/offline/offline_tasks.h"

namespace semnav::modelproxy::offline {

inline constexpr char kOfflineModel[] = "conceptnet-atlocation-prior";

class OfflineBackend : public Backend {
 public:
  OfflineBackend(PlacePrior prior, OfflineParams params)
      : prior_(std::move(prior)), params_(params) {}

  // INVALID_ARGUMENT when no text part of the last user message is a JSON task object, or the
  // task is malformed (the message names the field).
  absl::StatusOr<BackendReply> Complete(const CompletionRequest& request,
                                        absl::Time deadline) override;
  absl::StatusOr<EmbeddingReply> Embed(const EmbeddingRequest& request,
                                       absl::Time deadline) override;
  std::string model() const override { return kOfflineModel; }
  std::string endpoint() const override { return ""; }
  bool configured() const override { return true; }

 private:
  const PlacePrior prior_;
  const OfflineParams params_;
};

}  // namespace semnav::modelproxy::offline
