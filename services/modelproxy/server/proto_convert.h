#pragma once
// Proto <-> core conversion for the model proxy. Request conversion checks what only the proto
// can get wrong (unset oneofs, image encodings); the core validates the rest.
#include "absl/status/statusor.h"
#include "semnav/modelproxy/v1/modelproxy.pb.h"
#include "services/modelproxy/core/model_proxy.h"

namespace semnav::modelproxy {

// INVALID_ARGUMENT with an ErrorInfo naming the field (e.g. "messages[0].parts[1].image.encoding").
absl::StatusOr<CompletionRequest> ToCore(const v1::CompleteRequest& request);
EmbeddingRequest ToCore(const v1::EmbedRequest& request);

void ToProto(const CompletionResult& result, v1::CompleteResponse* response);
void ToProto(const EmbeddingResult& result, v1::EmbedResponse* response);
void ToProto(const BackendStatus& status, v1::BackendInfo* info);
void ToProto(const UsageRow& row, v1::UsageRecord* record);

}  // namespace semnav::modelproxy
