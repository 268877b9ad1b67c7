// How semnavctl reports results and errors: JSON of the response messages, typed error lines on
// stderr, and the exit code of a status.
#pragma once

#include <google/protobuf/message.h>

#include <string>

#include "absl/status/status.h"

namespace semnav::cli {

// The message as one line of JSON (proto field names, enums by name, zero values included).
std::string ToJson(const google::protobuf::Message& message);
void PrintJson(const google::protobuf::Message& message);

// Prints "semnavctl: CODE: message [ErrorInfo reason]" to stderr and returns the exit code for the
// status.
int Fail(const absl::Status& status);
// Prints "semnavctl: message" to stderr and returns the usage exit code.
int UsageError(const std::string& message);

// Reads a file whose content is the JSON form of `message` (unknown fields are errors).
absl::Status ReadJsonFile(const std::string& flag, const std::string& path,
                          google::protobuf::Message* message);

}  // namespace semnav::cli
