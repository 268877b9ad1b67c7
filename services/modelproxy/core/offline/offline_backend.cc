#include "services/modelproxy/core/offline/offline_backend.h"

#include "absl/status/status.h"
#include "absl/strings/ascii.h"

namespace semnav::modelproxy::offline {
namespace {

// The last text part of the last user message that parses as a JSON object with "task".
const nlohmann::json* FindTask(const CompletionRequest& request, nlohmann::json& storage) {
  for (auto m = request.messages.rbegin(); m != request.messages.rend(); ++m) {
    if (m->role != Role::kUser) continue;
    for (auto p = m->parts.rbegin(); p != m->parts.rend(); ++p) {
      const absl::string_view text = absl::StripAsciiWhitespace(p->text);
      if (p->is_image() || text.empty() || text.front() != '{') continue;
      storage = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
      if (storage.is_object() && storage.contains("task")) return &storage;
    }
    return nullptr;
  }
  return nullptr;
}

}  // namespace

absl::StatusOr<BackendReply> OfflineBackend::Complete(const CompletionRequest& request,
                                                      absl::Time /*deadline*/) {
  nlohmann::json storage;
  const nlohmann::json* task = FindTask(request, storage);
  if (task == nullptr) {
    return absl::InvalidArgumentError(
        "messages[-1].parts: the offline backend needs a JSON task object "
        "(match_target, rank_regions or decompose) as a text part of the last user message");
  }
  absl::StatusOr<nlohmann::json> answer = RunOfflineTask(*task, prior_, params_);
  if (!answer.ok()) return answer.status();
  BackendReply reply;
  reply.text = answer->dump();
  reply.model = kOfflineModel;
  reply.offline = true;
  reply.provenance = kPriorProvenance;
  return reply;
}

absl::StatusOr<EmbeddingReply> OfflineBackend::Embed(const EmbeddingRequest& /*request*/,
                                                     absl::Time /*deadline*/) {
  return absl::UnimplementedError("the offline backend has no text encoder");
}

}  // namespace semnav::modelproxy::offline
