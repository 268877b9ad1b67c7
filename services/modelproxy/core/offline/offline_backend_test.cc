#include "services/modelproxy/core/offline/offline_backend.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy::offline {
namespace {

OfflineBackend MakeBackend() {
  return OfflineBackend(
      *PlacePrior::Load(std::string(SEMNAV_SHARED_DATA_DIR) +
                        "/object-priors/conceptnet_atlocation_coco80/conceptnet-data.json"),
      OfflineParams());
}

TEST(ModelProxyOfflineBackendTest, AnswersTheJsonTaskPartAndMarksItOffline) {
  OfflineBackend backend = MakeBackend();
  CompletionRequest r;
  r.messages = {ChatMessage{Role::kSystem, {ContentPart{"You rank regions.", "", ""}}},
                ChatMessage{Role::kUser,
                            {ContentPart{"Which region?", "", ""},
                             ContentPart{R"({"task":"match_target","target":"sofa",
                                             "candidates":[{"id":"a","label":"couch"}]})",
                                         "", ""},
                             ContentPart{"", "\x89PNG", "image/png"}}}};
  const auto reply = backend.Complete(r, absl::InfiniteFuture());
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_TRUE(reply->offline);
  EXPECT_EQ(reply->model, "conceptnet-atlocation-prior");
  EXPECT_NE(reply->provenance.find("ConceptNet"), std::string::npos);
  const nlohmann::json answer = nlohmann::json::parse(reply->text);
  EXPECT_EQ(answer["best_id"], "a");
  EXPECT_EQ(answer["confidence"], 1.0);
  EXPECT_EQ(reply->usage.input_tokens, 0);
}

TEST(ModelProxyOfflineBackendTest, FreeTextIsInvalidArgumentAndEmbeddingsUnimplemented) {
  OfflineBackend backend = MakeBackend();
  CompletionRequest r;
  r.messages = {ChatMessage{Role::kUser, {ContentPart{"write a poem {about chairs}", "", ""}}}};
  const auto reply = backend.Complete(r, absl::InfiniteFuture());
  EXPECT_EQ(reply.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(reply.status().message().find("messages[-1].parts"), std::string::npos);
  EXPECT_EQ(backend.Embed({"x", {"chair"}}, absl::InfiniteFuture()).status().code(),
            absl::StatusCode::kUnimplemented);
}

}  // namespace
}  // namespace semnav::modelproxy::offline
