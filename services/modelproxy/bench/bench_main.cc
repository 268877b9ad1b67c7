// semnav-bench-modelproxy: proxy overhead, throughput and fallback switch time against the
// local scripted vendor server (no network, no keys).
//
//   semnav-bench-modelproxy [--json FILE] [--calls N] [--callers N] [--seconds S]
//
// overhead_ms_*: per call, proxy latency minus the latency of the same request POSTed straight
//   to the same vendor with the same HTTP client (interleaved pairs): what the proxy adds
//   (validation, cache key, breaker/limiter, body build and answer parsing).
// overhead_vs_handler_ms_*: proxy latency minus the vendor handler's own time, i.e. also
//   counting the loopback HTTP hop: an upper bound.
// direct_http_ms_*: the direct call alone, for scale.
// calls_per_s: answered calls per second with --callers threads calling at once (cache off).
// fallback_ms_p50: primary refuses connections (breaker disabled so every call tries it);
//   time from call start until the fallback's attempt starts.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "nlohmann/json.hpp"
#include "services/common/cli/flags.h"
#include "services/modelproxy/core/http_backend.h"
#include "services/modelproxy/core/model_proxy.h"
#include "services/modelproxy/core/openai_wire.h"
#include "services/modelproxy/testing/fake_vendor_server.h"

namespace semnav::modelproxy {
namespace {

struct Flags {
  std::string json_path;
  int calls = 3000;
  int callers = 64;
  double seconds = 3.0;
};

constexpr char kUsage[] =
    "usage: semnav-bench-modelproxy [--json FILE] [--calls N] [--callers N] [--seconds S]\n"
    "Proxy overhead per call beyond the backend's own time, throughput with concurrent\n"
    "callers, and fallback switch time, against a local OpenAI-format test server.\n";

// Exits (ParseFlagsOrExit) on unknown flags and missing values; nullopt after printing the
// reason and the usage for out-of-range values.
std::optional<Flags> ReadFlags(int argc, char** argv) {
  const ParsedFlags parsed = ParseFlagsOrExit(
      argc, argv,
      {{"json", "FILE", ""}, {"calls", "N", ""}, {"callers", "N", ""}, {"seconds", "S", ""}},
      "semnav-bench-modelproxy", kUsage);
  Flags f;
  f.json_path = parsed.Get("json").value_or(f.json_path);
  std::string bad;
  if (auto v = parsed.Get("calls"); v && !(absl::SimpleAtoi(*v, &f.calls) && f.calls >= 3)) {
    bad = "--calls: expected an integer >= 3";
  } else if (auto v = parsed.Get("callers");
             v && !(absl::SimpleAtoi(*v, &f.callers) && f.callers >= 1)) {
    bad = "--callers: expected an integer >= 1";
  } else if (auto v = parsed.Get("seconds");
             v && !(absl::SimpleAtod(*v, &f.seconds) && f.seconds > 0)) {
    bad = "--seconds: expected a number > 0";
  }
  if (!bad.empty()) {
    std::cerr << "semnav-bench-modelproxy: " << bad << "\n" << kUsage;
    return std::nullopt;
  }
  return f;
}

double Percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

BackendPolicy BenchPolicy() {
  BackendPolicy p;
  p.timeout = absl::Seconds(5);
  p.retry.max_attempts = 1;
  p.breaker.failure_threshold = 1 << 30;  // never open: every call pays the failed attempt
  p.max_in_flight = 256;
  return p;
}

std::unique_ptr<Backend> OpenAi(const std::string& url,
                                const std::shared_ptr<HttpTransport>& transport) {
  return std::make_unique<HttpBackend>(
      HttpBackendSpec{BackendKind::kOpenAi, url, "bench-model", 64, false}, ApiKey(), transport);
}

CompletionRequest Request(int i) {
  CompletionRequest r;
  r.alias = "bench";
  r.bypass_cache = true;
  r.messages = {
      ChatMessage{Role::kSystem, {ContentPart{"You pick the most promising region.", "", ""}}},
      ChatMessage{Role::kUser,
                  {ContentPart{absl::StrCat("Where is the toilet? call ", i), "", ""}}}};
  return r;
}

std::unique_ptr<ModelProxy> MakeProxy(
    std::vector<std::pair<std::string, std::string>> backends,
    std::shared_ptr<HttpTransport> transport = std::make_shared<HttpTransport>()) {
  auto proxy = std::make_unique<ModelProxy>(ProxyOptions{});
  std::vector<std::string> chain;
  for (const auto& [name, url] : backends) {
    if (!proxy->AddBackend({name, "openai", OpenAi(url, transport), BenchPolicy()}).ok())
      std::abort();
    chain.push_back(name);
  }
  if (!proxy->AddAlias("bench", chain).ok()) std::abort();
  return proxy;
}

struct OverheadSamples {
  std::vector<double> paired;      // proxy call minus the adjacent direct HTTP call (ms)
  std::vector<double> vs_handler;  // proxy call minus the vendor handler's own time (ms)
  std::vector<double> direct;      // direct HTTP call (ms)
  std::vector<double> proxied;     // the call through the proxy (ms)
};

// Interleaved pairs: the same chat body POSTed straight through the HTTP client (what a caller
// talking to the vendor itself would wait), then the same request through the proxy. Both use
// one transport, hence the same keep-alive connection.
OverheadSamples MeasureOverhead(testing::FakeVendorServer& vendor, int calls) {
  auto transport = std::make_shared<HttpTransport>();
  auto proxy = MakeProxy({{"primary", vendor.base_url()}}, transport);
  const OpenAiWire wire;
  const std::string url = vendor.base_url() + "/chat/completions";
  OverheadSamples out;
  for (int i = 0; i < calls + 200; ++i) {  // the first 200 pairs warm up connections and caches
    const CompletionRequest request = Request(i);
    absl::Time start = absl::Now();
    if (!transport
             ->Post(url, wire.Headers(""), wire.ChatBody(request, "bench-model", 64),
                    start + absl::Seconds(5))
             .ok()) {
      std::abort();
    }
    const double direct_ms = absl::ToDoubleMilliseconds(absl::Now() - start);
    vendor.ClearHandlerTimes();
    start = absl::Now();
    if (!proxy->Complete(request, {}, start + absl::Seconds(5)).ok()) std::abort();
    const double proxy_ms = absl::ToDoubleMilliseconds(absl::Now() - start);
    if (i < 200) continue;
    out.direct.push_back(direct_ms);
    out.proxied.push_back(proxy_ms);
    out.paired.push_back(proxy_ms - direct_ms);
    out.vs_handler.push_back(proxy_ms - absl::ToDoubleMilliseconds(vendor.handler_times().at(0)));
  }
  return out;
}

double MeasureThroughput(testing::FakeVendorServer& vendor, int callers, double seconds) {
  auto proxy = MakeProxy({{"primary", vendor.base_url()}});
  std::atomic<int64_t> answered{0};
  std::atomic<bool> failed{false};
  const absl::Time start = absl::Now();
  const absl::Time end = start + absl::Seconds(seconds);
  std::vector<std::thread> threads;
  for (int t = 0; t < callers; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; absl::Now() < end; ++i) {
        if (proxy->Complete(Request(t * 1000000 + i), {}, absl::Now() + absl::Seconds(5)).ok()) {
          ++answered;
        } else {
          failed = true;
        }
      }
    });
  }
  for (std::thread& t : threads) t.join();
  if (failed) std::cerr << "warning: some throughput calls failed\n";
  return static_cast<double>(answered.load()) / absl::ToDoubleSeconds(absl::Now() - start);
}

// Time from call start until the fallback's (last) attempt started.
std::vector<double> MeasureFallback(const std::string& primary_url,
                                    testing::FakeVendorServer& vendor, int calls) {
  auto proxy = MakeProxy({{"primary", primary_url}, {"secondary", vendor.base_url()}});
  std::vector<double> switch_ms;
  for (int i = 0; i < calls; ++i) {
    const absl::Time start = absl::Now();
    absl::StatusOr<CompletionResult> r = proxy->Complete(Request(i), {}, start + absl::Seconds(5));
    const absl::Duration total = absl::Now() - start;
    if (!r.ok() || r->backend != "secondary") std::abort();
    switch_ms.push_back(absl::ToDoubleMilliseconds(total - r->attempts.back().latency));
  }
  return switch_ms;
}

}  // namespace

int Main(int argc, char** argv) {
  const std::optional<Flags> parsed = ReadFlags(argc, argv);
  if (!parsed) return 2;
  const Flags& flags = *parsed;
  testing::FakeVendorServer vendor;
  const OverheadSamples overhead = MeasureOverhead(vendor, flags.calls);
  const double calls_per_s = MeasureThroughput(vendor, flags.callers, flags.seconds);
  const std::vector<double> refused =
      MeasureFallback("http://127.0.0.1:1/v1", vendor, flags.calls / 3);
  testing::FakeVendorServer failing;
  failing.SetDefault(testing::Route::kOpenAiChat, testing::Action::Status(503));
  const std::vector<double> http503 = MeasureFallback(failing.base_url(), vendor, flags.calls / 3);

  const nlohmann::json figures = {
      {"overhead_ms_p50", Percentile(overhead.paired, 0.50)},
      {"overhead_ms_p99", Percentile(overhead.paired, 0.99)},
      {"overhead_vs_handler_ms_p50", Percentile(overhead.vs_handler, 0.50)},
      {"overhead_vs_handler_ms_p99", Percentile(overhead.vs_handler, 0.99)},
      {"calls_per_s", calls_per_s},
      {"direct_http_ms_p50", Percentile(overhead.direct, 0.50)},
      {"direct_http_ms_p99", Percentile(overhead.direct, 0.99)},
      {"proxy_call_ms_p50", Percentile(overhead.proxied, 0.50)},
      {"fallback_ms_p50", Percentile(refused, 0.50)},
      {"fallback_ms_p99", Percentile(refused, 0.99)},
      {"fallback_503_ms_p50", Percentile(http503, 0.50)},
      {"callers", flags.callers},
      {"overhead_calls", static_cast<int64_t>(overhead.paired.size())},
  };
  std::cout << absl::StrFormat("%-22s %12s\n", "figure", "value");
  for (const auto& [name, value] : figures.items()) {
    std::cout << absl::StrFormat("%-22s %12.4f\n", name, value.get<double>());
  }
  if (!flags.json_path.empty()) std::ofstream(flags.json_path) << figures.dump(2) << "\n";
  return 0;
}

}  // namespace semnav::modelproxy

int main(int argc, char** argv) { return semnav::modelproxy::Main(argc, argv); }
