#include "services/modelproxy/testing/fake_vendor_server.h"

#include <httplib.h>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"

namespace semnav::modelproxy::testing {
namespace {

std::string AnswerBody(Route route, const std::string& text, const std::string& request_body) {
  const nlohmann::json request = nlohmann::json::parse(request_body, nullptr, false);
  const std::string model = request.is_object() ? request.value("model", "") : "";
  switch (route) {
    case Route::kAnthropicMessages:
      return nlohmann::json{{"id", "msg_1"},
                            {"type", "message"},
                            {"model", model},
                            {"content", {{{"type", "text"}, {"text", text}}}},
                            {"stop_reason", "end_turn"},
                            {"usage", {{"input_tokens", 11}, {"output_tokens", 7}}}}
          .dump();
    case Route::kOpenAiEmbeddings: {
      nlohmann::json data = nlohmann::json::array();
      const size_t n =
          request.is_object() && request.contains("input") ? request["input"].size() : 0;
      for (size_t i = 0; i < n; ++i) {
        data.push_back({{"index", i}, {"embedding", {1.0 + i, 0.5, -0.25}}});
      }
      return nlohmann::json{{"data", data}, {"model", model}, {"usage", {{"prompt_tokens", 3 * n}}}}
          .dump();
    }
    case Route::kOpenAiChat:
      break;
  }
  return nlohmann::json{{"id", "chatcmpl-1"},
                        {"model", model},
                        {"choices",
                         {{{"index", 0},
                           {"message", {{"role", "assistant"}, {"content", text}}},
                           {"finish_reason", "stop"}}}},
                        {"usage", {{"prompt_tokens", 13}, {"completion_tokens", 5}}}}
      .dump();
}

}  // namespace

FakeVendorServer::FakeVendorServer() : server_(std::make_unique<httplib::Server>()) {
  server_->new_task_queue = [] { return new httplib::ThreadPool(96); };
  server_->set_tcp_nodelay(true);             // else Nagle + delayed ACK add ~40 ms per answer
  server_->set_keep_alive_max_count(100000);  // keep connections like a vendor API does
  const std::pair<Route, const char*> routes[] = {{Route::kOpenAiChat, "/v1/chat/completions"},
                                                  {Route::kAnthropicMessages, "/v1/messages"},
                                                  {Route::kOpenAiEmbeddings, "/v1/embeddings"}};
  for (const auto& [route, path] : routes) {
    const Route r = route;
    server_->Post(path, [this, r](const httplib::Request& req, httplib::Response& res) {
      const absl::Time start = absl::Now();
      SeenRequest seen{req.body, {}};
      for (const auto& [name, value] : req.headers)
        seen.headers[absl::AsciiStrToLower(name)] = value;
      const std::string auth = seen.headers.count("authorization") ? seen.headers["authorization"]
                                                                   : seen.headers["x-api-key"];
      const Action action = Next(r, std::move(seen));
      if (action.delay > absl::ZeroDuration()) absl::SleepFor(action.delay);
      for (const auto& [name, value] : action.headers) res.set_header(name, value);
      switch (action.kind) {
        case Action::Kind::kAnswer:
          res.set_content(AnswerBody(r, action.text, req.body), "application/json");
          break;
        case Action::Kind::kMalformedJson:
          res.set_content("{\"choices\": [ {\"message\": ", "application/json");
          break;
        case Action::Kind::kStatus:
          res.status = action.status;
          res.set_content(
              nlohmann::json{{"error", {{"message", absl::StrCat("scripted ", action.status)}}}}
                  .dump(),
              "application/json");
          break;
        case Action::Kind::kEchoKeyError:
          res.status = 401;
          res.set_content(nlohmann::json{{"error", {{"message", "invalid key: " + auth}}}}.dump(),
                          "application/json");
          break;
        case Action::Kind::kTruncated: {
          const std::string full = AnswerBody(r, action.text, req.body);
          res.set_content_provider(full.size(), "application/json",
                                   [full](size_t offset, size_t, httplib::DataSink& sink) {
                                     if (offset == 0) sink.write(full.data(), full.size() / 2);
                                     return false;  // drop the connection mid-body
                                   });
          break;
        }
      }
      absl::MutexLock lock(&mu_);
      handler_times_.push_back(absl::Now() - start);
    });
  }
  port_ = server_->bind_to_any_port("127.0.0.1");
  thread_ = std::thread([this] { server_->listen_after_bind(); });
  while (!server_->is_running()) absl::SleepFor(absl::Milliseconds(1));
}

FakeVendorServer::~FakeVendorServer() {
  server_->stop();
  thread_.join();
}

std::string FakeVendorServer::base_url() const {
  return absl::StrCat("http://127.0.0.1:", port_, "/v1");
}

void FakeVendorServer::Script(Route route, std::vector<Action> actions) {
  absl::MutexLock lock(&mu_);
  scripts_[route] = std::deque<Action>(actions.begin(), actions.end());
}

void FakeVendorServer::SetDefault(Route route, Action action) {
  absl::MutexLock lock(&mu_);
  defaults_[route] = std::move(action);
}

int FakeVendorServer::requests(Route route) const {
  absl::MutexLock lock(&mu_);
  auto it = seen_.find(route);
  return it == seen_.end() ? 0 : static_cast<int>(it->second.size());
}

std::vector<SeenRequest> FakeVendorServer::seen(Route route) const {
  absl::MutexLock lock(&mu_);
  auto it = seen_.find(route);
  return it == seen_.end() ? std::vector<SeenRequest>() : it->second;
}

std::vector<absl::Duration> FakeVendorServer::handler_times() const {
  absl::MutexLock lock(&mu_);
  return handler_times_;
}

void FakeVendorServer::ClearHandlerTimes() {
  absl::MutexLock lock(&mu_);
  handler_times_.clear();
}

Action FakeVendorServer::Next(Route route, SeenRequest seen) {
  absl::MutexLock lock(&mu_);
  seen_[route].push_back(std::move(seen));
  std::deque<Action>& script = scripts_[route];
  if (script.empty()) {
    auto it = defaults_.find(route);
    return it == defaults_.end() ? Action::Answer("ok") : it->second;
  }
  Action action = script.front();
  script.pop_front();
  return action;
}

}  // namespace semnav::modelproxy::testing
