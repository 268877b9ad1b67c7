#include "clients/cli/output.h"

#include <google/protobuf/util/json_util.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "clients/cli/core/exit_codes.h"
#include "semnav/common/v1/errors.pb.h"
#include "services/common/status/grpc_status.h"

namespace semnav::cli {

std::string ToJson(const google::protobuf::Message& message) {
  google::protobuf::util::JsonPrintOptions options;
  options.preserve_proto_field_names = true;
  options.always_print_primitive_fields = true;
  std::string json;
  if (!google::protobuf::util::MessageToJsonString(message, &json, options).ok()) return "{}";
  return json;
}

void PrintJson(const google::protobuf::Message& message) {
  std::cout << ToJson(message) << std::endl;
}

int Fail(const absl::Status& status) {
  std::cerr << "semnavctl: " << absl::StatusCodeToString(status.code()) << ": " << status.message();
  std::optional<common::v1::ErrorInfo> info = GetDetail<common::v1::ErrorInfo>(status);
  if (info && !info->reason().empty() &&
      info->reason() != absl::StatusCodeToString(status.code())) {
    std::cerr << " [" << info->reason() << "]";
  }
  std::cerr << std::endl;
  return ToInt(ExitCodeFor(status.code()));
}

int UsageError(const std::string& message) {
  const bool hinted = message.find("--help") != std::string::npos;
  std::cerr << "semnavctl: " << message << (hinted ? "" : " (see --help)") << std::endl;
  return ToInt(ExitCode::kUsage);
}

absl::Status ReadJsonFile(const std::string& flag, const std::string& path,
                          google::protobuf::Message* message) {
  std::ifstream in(path);
  if (!in)
    return absl::InvalidArgumentError(absl::StrCat("--", flag, ": cannot read '", path, "'"));
  std::stringstream content;
  content << in.rdbuf();
  google::protobuf::util::JsonParseOptions options;
  auto parsed = google::protobuf::util::JsonStringToMessage(content.str(), message, options);
  if (!parsed.ok()) {
    return absl::InvalidArgumentError(absl::StrCat("--", flag, ": '", path, "' is not a ",
                                                   message->GetTypeName(),
                                                   " in JSON: ", parsed.message().ToString()));
  }
  return absl::OkStatus();
}

}  // namespace semnav::cli
