#pragma once
// A local HTTP server speaking the OpenAI (chat completions, embeddings) and Anthropic
// (messages) wire formats, scripted per test: each route answers from a queue of actions
// (good answer, malformed JSON, 429, 500, slow, truncated body, error echoing the key) and
// falls back to a default action when the queue is empty. For tests and the benchmark only.
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

namespace httplib {
class Server;
}

namespace semnav::modelproxy::testing {

enum class Route { kOpenAiChat, kAnthropicMessages, kOpenAiEmbeddings };

struct Action {
  enum class Kind { kAnswer, kMalformedJson, kStatus, kTruncated, kEchoKeyError };
  Kind kind = Kind::kAnswer;
  std::string text = "ok";                     // answer text (kAnswer)
  int status = 200;                            // HTTP status (kStatus)
  absl::Duration delay;                        // sleep before answering (any kind)
  std::map<std::string, std::string> headers;  // extra response headers (any kind)

  static Action Answer(std::string text) { return {Kind::kAnswer, std::move(text), 200, {}, {}}; }
  static Action Malformed() { return {Kind::kMalformedJson, "", 200, {}, {}}; }
  static Action Status(int http_status) { return {Kind::kStatus, "", http_status, {}, {}}; }
  static Action Truncated() { return {Kind::kTruncated, "", 200, {}, {}}; }
  static Action EchoKey() { return {Kind::kEchoKeyError, "", 401, {}, {}}; }
  Action WithHeader(std::string name, std::string value) const {
    Action a = *this;
    a.headers[std::move(name)] = std::move(value);
    return a;
  }
  Action Slow(absl::Duration d) const {
    Action a = *this;
    a.delay = d;
    return a;
  }
};

struct SeenRequest {
  std::string body;
  std::map<std::string, std::string> headers;  // lower-case names
};

class FakeVendorServer {
 public:
  FakeVendorServer();  // listens on 127.0.0.1:<free port>, serves on a background thread
  ~FakeVendorServer();

  // "http://127.0.0.1:<port>/v1"
  std::string base_url() const;
  void Script(Route route, std::vector<Action> actions);
  void SetDefault(Route route, Action action);
  int requests(Route route) const;
  std::vector<SeenRequest> seen(Route route) const;
  // Wall time spent inside handlers, one entry per request in arrival order (for the bench).
  std::vector<absl::Duration> handler_times() const;
  void ClearHandlerTimes();

 private:
  Action Next(Route route, SeenRequest seen);

  std::unique_ptr<httplib::Server> server_;
  int port_ = 0;
  std::thread thread_;
  mutable absl::Mutex mu_;
  std::map<Route, std::deque<Action>> scripts_ ABSL_GUARDED_BY(mu_);
  std::map<Route, Action> defaults_ ABSL_GUARDED_BY(mu_);
  std::map<Route, std::vector<SeenRequest>> seen_ ABSL_GUARDED_BY(mu_);
  std::vector<absl::Duration> handler_times_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::modelproxy::testing
