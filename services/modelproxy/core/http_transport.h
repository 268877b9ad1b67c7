#pragma once
// Blocking HTTP(S) POST over libcurl, bounded by an absolute deadline. Easy handles are pooled
// so keep-alive connections (and TLS sessions) are reused across calls. Thread-safe.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"

namespace semnav::modelproxy {

struct HttpResponse {
  long status = 0;  // HTTP status code
  std::string body;
  std::map<std::string, std::string> headers;  // lower-case names
};

class HttpTransport {
 public:
  HttpTransport();
  ~HttpTransport();
  HttpTransport(const HttpTransport&) = delete;
  HttpTransport& operator=(const HttpTransport&) = delete;

  // Any HTTP status is a successful transport result. Errors: DEADLINE_EXCEEDED when the
  // deadline passes, DATA_LOSS for a body cut short, UNAVAILABLE when no connection could be
  // made. Messages never contain header values (keys travel in headers).
  absl::StatusOr<HttpResponse> Post(const std::string& url, const std::vector<std::string>& headers,
                                    const std::string& body, absl::Time deadline);

 private:
  void* TakeHandle();
  void ReturnHandle(void* handle);

  absl::Mutex mu_;
  std::vector<void*> idle_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::modelproxy
