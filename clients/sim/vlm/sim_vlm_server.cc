#include "clients/sim/vlm/sim_vlm_server.h"

#include <httplib.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "absl/strings/escaping.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "nlohmann/json.hpp"
#include "services/common/status/field_error.h"
#include "services/modelproxy/core/http_backend.h"

namespace semnav::sim::vlm {
namespace {

constexpr size_t kMaxBodyBytes = 32u << 20;
constexpr size_t kMaxImages = 8;
constexpr size_t kMaxEmbeddingInputs = 256;

absl::StatusOr<cv::Mat> DecodeDataUrl(const std::string& url) {
  const size_t comma = url.find(',');
  if (!absl::StartsWith(url, "data:image/") || comma == std::string::npos ||
      url.substr(0, comma).find(";base64") == std::string::npos) {
    return InvalidField("messages.content.image_url.url", "must be a base64 data:image/... URL");
  }
  std::string bytes;
  if (!absl::Base64Unescape(absl::string_view(url).substr(comma + 1), &bytes)) {
    return InvalidField("messages.content.image_url.url", "is not valid base64");
  }
  const cv::Mat raw(1, static_cast<int>(bytes.size()), CV_8UC1, bytes.data());
  cv::Mat image = cv::imdecode(raw, cv::IMREAD_COLOR);
  if (image.empty())
    return InvalidField("messages.content.image_url.url", "is not a decodable image");
  return image;
}

std::string ErrorBody(const absl::Status& status) {
  return nlohmann::json{
      {"error", {{"message", std::string(status.message())}, {"type", "invalid_request_error"}}}}
      .dump();
}

}  // namespace

absl::StatusOr<VlmQuestion> ParseChatBody(const std::string& body) {
  if (body.size() > kMaxBodyBytes) return InvalidField("body", "is larger than 32 MiB");
  const nlohmann::json json = nlohmann::json::parse(body, nullptr, false);
  if (!json.is_object() || !json.contains("messages") || !json["messages"].is_array()) {
    return InvalidField("messages", "must be an array");
  }
  VlmQuestion question;
  for (const nlohmann::json& message : json["messages"]) {
    const nlohmann::json content =
        message.is_object() ? message.value("content", nlohmann::json()) : nlohmann::json();
    if (content.is_string()) {
      absl::StrAppend(&question.text, question.text.empty() ? "" : "\n",
                      content.get<std::string>());
      continue;
    }
    if (!content.is_array())
      return InvalidField("messages.content", "must be a string or an array of parts");
    for (const nlohmann::json& part : content) {
      const std::string type = part.is_object() ? part.value("type", "") : "";
      if (type == "text" && part.value("text", nlohmann::json()).is_string()) {
        absl::StrAppend(&question.text, question.text.empty() ? "" : "\n",
                        part["text"].get<std::string>());
      } else if (type == "image_url" && part.contains("image_url") &&
                 part["image_url"].is_object() &&
                 part["image_url"].value("url", nlohmann::json()).is_string()) {
        if (question.images.size() >= kMaxImages)
          return InvalidField("messages.content", "at most 8 images");
        absl::StatusOr<cv::Mat> image = DecodeDataUrl(part["image_url"]["url"].get<std::string>());
        if (!image.ok()) return image.status();
        question.images.push_back(*std::move(image));
      } else {
        return InvalidField("messages.content.type", "must be text or image_url");
      }
    }
  }
  return question;
}

absl::StatusOr<std::vector<std::string>> ParseEmbeddingsBody(const std::string& body) {
  if (body.size() > kMaxBodyBytes) return InvalidField("body", "is larger than 32 MiB");
  const nlohmann::json json = nlohmann::json::parse(body, nullptr, false);
  const nlohmann::json input =
      json.is_object() ? json.value("input", nlohmann::json()) : nlohmann::json();
  std::vector<std::string> texts;
  if (input.is_string()) {
    texts.push_back(input.get<std::string>());
  } else if (input.is_array() && !input.empty() && input.size() <= kMaxEmbeddingInputs) {
    for (const nlohmann::json& text : input) {
      if (!text.is_string()) return InvalidField("input", "must hold strings");
      texts.push_back(text.get<std::string>());
    }
  } else {
    return InvalidField("input", "must be a string or 1..256 strings");
  }
  for (const std::string& text : texts) {
    if (text.empty()) return InvalidField("input", "texts must not be empty");
  }
  return texts;
}

SimVlmServer::SimVlmServer(std::unique_ptr<SimVlm> model)
    : model_(std::move(model)), server_(std::make_unique<httplib::Server>()) {}

absl::StatusOr<std::unique_ptr<SimVlmServer>> SimVlmServer::Start(std::unique_ptr<SimVlm> model,
                                                                  int port) {
  if (model == nullptr) return absl::InvalidArgumentError("model: required");
  if (port < 0 || port > 65535) return InvalidField("port", "must be 0..65535");
  std::unique_ptr<SimVlmServer> server(new SimVlmServer(std::move(model)));
  SimVlmServer* self = server.get();
  self->server_->set_tcp_nodelay(true);
  self->server_->set_payload_max_length(kMaxBodyBytes);
  // Counts the request and checks the key; false (with the 401 written) for a wrong key.
  auto admit = [self](const httplib::Request& req, httplib::Response& res, const SimVlm& model) {
    {
      absl::MutexLock lock(&self->mu_);
      ++self->requests_;
    }
    const std::string& key = model.config().api_key;
    if (!key.empty() && req.get_header_value("Authorization") != absl::StrCat("Bearer ", key)) {
      res.status = 401;
      res.set_content(ErrorBody(absl::UnauthenticatedError("invalid API key")), "application/json");
      return false;
    }
    return true;
  };
  self->server_->Post("/v1/embeddings", [self, admit](const httplib::Request& req,
                                                      httplib::Response& res) {
    const std::shared_ptr<const SimVlm> model = self->model();
    if (!admit(req, res, *model)) return;
    absl::StatusOr<std::vector<std::string>> texts = ParseEmbeddingsBody(req.body);
    if (!texts.ok()) {
      res.status = 400;
      res.set_content(ErrorBody(texts.status()), "application/json");
      return;
    }
    nlohmann::json data = nlohmann::json::array();
    int tokens = 0;
    double latency_s = 0.0;  // the texts of one call are encoded as one batch
    for (size_t i = 0; i < texts->size(); ++i) {
      SimVlm::TextEmbedding embedded = model->EmbedText((*texts)[i]);
      latency_s = std::max(latency_s, embedded.latency_s);
      data.push_back(
          {{"object", "embedding"}, {"index", i}, {"embedding", std::move(embedded.vector)}});
      tokens += 1 + static_cast<int>((*texts)[i].size() / 4);
    }
    {
      absl::MutexLock lock(&self->mu_);
      ++self->served_.embedding_answers;
      self->served_.tokens += tokens;
      self->served_.latency_ms += std::llround(1000.0 * latency_s);
    }
    const nlohmann::json request = nlohmann::json::parse(req.body, nullptr, false);
    // Stated like a chat answer's, so the encoder's time is simulated time too: without it the
    // proxy reported its wall time, and when the embedding arrived depended on the machine's load.
    res.set_header(modelproxy::kSimulatedLatencyHeader, absl::StrFormat("%.3f", latency_s));
    res.set_content(nlohmann::json{{"object", "list"},
                                   {"data", data},
                                   {"model", request.value("model", "sim-vlm")},
                                   {"usage", {{"prompt_tokens", tokens}, {"total_tokens", tokens}}}}
                        .dump(),
                    "application/json");
  });
  self->server_->Post("/v1/chat/completions", [self, admit](const httplib::Request& req,
                                                            httplib::Response& res) {
    const std::shared_ptr<const SimVlm> model = self->model();
    if (!admit(req, res, *model)) return;
    absl::StatusOr<VlmQuestion> question = ParseChatBody(req.body);
    absl::StatusOr<VlmReply> reply = question.ok() ? model->Answer(*question) : question.status();
    if (!reply.ok()) {
      res.status = 400;
      res.set_content(ErrorBody(reply.status()), "application/json");
      return;
    }
    {
      absl::MutexLock lock(&self->mu_);
      ++self->served_.answers;
      if (!question->images.empty()) ++self->served_.vision_answers;
      self->served_.tokens += reply->input_tokens + reply->output_tokens;
      self->served_.latency_ms += std::llround(1000.0 * reply->latency_s);
      self->answers_.push_back(reply->text.substr(0, 200));
      if (self->answers_.size() > 1000) self->answers_.pop_front();
    }
    const nlohmann::json request = nlohmann::json::parse(req.body, nullptr, false);
    res.set_header(modelproxy::kSimulatedLatencyHeader, absl::StrFormat("%.3f", reply->latency_s));
    res.set_content(
        nlohmann::json{{"id", "simvlm"},
                       {"object", "chat.completion"},
                       {"model", request.value("model", "sim-vlm")},
                       {"choices",
                        {{{"index", 0},
                          {"message", {{"role", "assistant"}, {"content", reply->text}}},
                          {"finish_reason", "stop"}}}},
                       {"usage",
                        {{"prompt_tokens", reply->input_tokens},
                         {"completion_tokens", reply->output_tokens},
                         {"total_tokens", reply->input_tokens + reply->output_tokens}}}}
            .dump(),
        "application/json");
  });
  self->port_ = port == 0 ? self->server_->bind_to_any_port("127.0.0.1")
                          : (self->server_->bind_to_port("127.0.0.1", port) ? port : -1);
  if (self->port_ <= 0)
    return absl::UnavailableError(absl::StrCat("cannot listen on 127.0.0.1:", port));
  self->thread_ = std::thread([self] { self->server_->listen_after_bind(); });
  while (!self->server_->is_running()) absl::SleepFor(absl::Milliseconds(1));
  return server;
}

SimVlmServer::~SimVlmServer() {
  server_->stop();
  if (thread_.joinable()) thread_.join();
}

void SimVlmServer::Replace(std::unique_ptr<SimVlm> model) {
  if (model == nullptr) return;
  absl::MutexLock lock(&mu_);
  model_ = std::move(model);
}

std::shared_ptr<const SimVlm> SimVlmServer::model() const {
  absl::MutexLock lock(&mu_);
  return model_;
}

std::string SimVlmServer::base_url() const {
  return absl::StrCat("http://127.0.0.1:", port_, "/v1");
}

SimVlmServer::Served SimVlmServer::served() const {
  absl::MutexLock lock(&mu_);
  return served_;
}

std::vector<std::string> SimVlmServer::answers() const {
  absl::MutexLock lock(&mu_);
  return std::vector<std::string>(answers_.begin(), answers_.end());
}

int SimVlmServer::requests() const {
  absl::MutexLock lock(&mu_);
  return requests_;
}

}  // namespace semnav::sim::vlm
