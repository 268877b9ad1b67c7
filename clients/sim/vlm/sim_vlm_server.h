// The simulated VLM behind the OpenAI-compatible wire (POST <base>/chat/completions, text and
// image_url data-URL parts; POST <base>/embeddings, the text encoder of the detector's embedding
// space, SimVlm::EmbedText), on 127.0.0.1: the model proxy
// reaches it like any vendor (kind openai, base_url, model, key from a file). Each answer states
// its simulated latency in the x-semnav-simulated-latency-s header, which the proxy reports as the
// call's latency.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "clients/sim/vlm/sim_vlm.h"

namespace httplib {
class Server;
}

namespace semnav::sim::vlm {

class SimVlmServer {
 public:
  // Listens on 127.0.0.1:`port` (0 = a free port) and serves on a background thread.
  static absl::StatusOr<std::unique_ptr<SimVlmServer>> Start(std::unique_ptr<SimVlm> model,
                                                             int port = 0);
  ~SimVlmServer();

  // Answers from `model` from now on (the next episode's world and frame log); calls being
  // answered finish with the old one.
  void Replace(std::unique_ptr<SimVlm> model);

  std::string base_url() const;  // "http://127.0.0.1:<port>/v1"
  int port() const { return port_; }
  int requests() const;
  // Totals over the answers served (for per-episode reports: take differences).
  struct Served {
    int answers = 0;
    int vision_answers = 0;     // of which about an image (the seed-000 search prompt)
    int embedding_answers = 0;  // /embeddings calls answered (not in `answers`)
    int64_t tokens = 0;         // input + output
    // Simulated model time in whole milliseconds (as stated): per-episode differences of a
    // running sum of doubles carried the rounding of the episodes before on the stack.
    int64_t latency_ms = 0;
  };
  Served served() const;
  // The answers served so far, oldest first (at most the last 1000), for episode timelines.
  std::vector<std::string> answers() const;

 private:
  explicit SimVlmServer(std::unique_ptr<SimVlm> model);

  mutable absl::Mutex mu_;
  std::shared_ptr<const SimVlm> model() const;

  std::shared_ptr<const SimVlm> model_ ABSL_GUARDED_BY(mu_);
  std::unique_ptr<httplib::Server> server_;
  int port_ = 0;
  std::thread thread_;
  int requests_ ABSL_GUARDED_BY(mu_) = 0;
  Served served_ ABSL_GUARDED_BY(mu_);
  std::deque<std::string> answers_ ABSL_GUARDED_BY(mu_);
};

// The OpenAI chat body as a question: text parts joined by newlines, image_url data URLs decoded
// (PNG/JPEG). INVALID_ARGUMENT naming the field for a malformed body.
absl::StatusOr<VlmQuestion> ParseChatBody(const std::string& body);

// The OpenAI embeddings body's texts: `input` is one string or 1..256 strings, none empty.
// INVALID_ARGUMENT naming the field otherwise.
absl::StatusOr<std::vector<std::string>> ParseEmbeddingsBody(const std::string& body);

}  // namespace semnav::sim::vlm
