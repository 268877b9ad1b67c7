#include "services/common/server/request_parse_interceptor.h"

#include <google/protobuf/descriptor.h>

#include <string>

#include "absl/status/status.h"
#include "absl/strings/cord.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/string_view.h"
#include "absl/strings/strip.h"
#include "services/common/status/field_error.h"
#include "services/common/status/grpc_status.h"

namespace semnav {
namespace {

using grpc::experimental::InterceptionHookPoints;
using grpc::experimental::ServerRpcInfo;

// "semnav.mapping.v1.GetGridMapRequest" for "/semnav.mapping.v1.MappingService/GetGridMap".
std::string RequestTypeName(absl::string_view method_path) {
  absl::string_view path = absl::StripPrefix(method_path, "/");
  size_t slash = path.rfind('/');
  if (slash == absl::string_view::npos) return "the request type";
  const google::protobuf::ServiceDescriptor* service =
      google::protobuf::DescriptorPool::generated_pool()->FindServiceByName(
          std::string(path.substr(0, slash)));
  const google::protobuf::MethodDescriptor* method =
      service == nullptr ? nullptr : service->FindMethodByName(std::string(path.substr(slash + 1)));
  if (method == nullptr) return "the request type";
  return method->input_type()->full_name();
}

class RequestParseInterceptor : public grpc::experimental::Interceptor {
 public:
  explicit RequestParseInterceptor(ServerRpcInfo* info) : info_(info) {}

  void Intercept(grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(InterceptionHookPoints::POST_RECV_MESSAGE) &&
        single_request() && methods->GetRecvMessage() == nullptr) {
      request_not_parsed_ = true;
    }
    if (request_not_parsed_ &&
        methods->QueryInterceptionHookPoint(InterceptionHookPoints::PRE_SEND_STATUS)) {
      grpc::Status sent = methods->GetSendStatus();
      // Only the status gRPC itself chose; a handler's own answer is left alone.
      if (sent.error_code() == grpc::StatusCode::UNIMPLEMENTED && sent.error_message().empty()) {
        absl::Status status(
            absl::StatusCode::kInvalidArgument,
            absl::StrCat("request: could not be parsed as ", RequestTypeName(info_->method()),
                         " (the bytes are not a valid protobuf serialization of it)"));
        status.SetPayload(kReasonPayloadUrl, absl::Cord(kRequestNotParsedReason));
        methods->ModifySendStatus(ToGrpcStatus(status));
      }
    }
    methods->Proceed();
  }

 private:
  // Unary and server-streaming handlers get their one request deserialized before they run.
  bool single_request() const {
    return info_->type() == ServerRpcInfo::Type::UNARY ||
           info_->type() == ServerRpcInfo::Type::SERVER_STREAMING;
  }

  ServerRpcInfo* info_;
  bool request_not_parsed_ = false;
};

}  // namespace

grpc::experimental::Interceptor* RequestParseInterceptorFactory::CreateServerInterceptor(
    ServerRpcInfo* info) {
  return new RequestParseInterceptor(info);
}

}  // namespace semnav
