#include "services/common/logging/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>

#include "absl/strings/ascii.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"

namespace semnav {
namespace {

std::atomic<int> g_level{static_cast<int>(LogLevel::kWarning)};
std::mutex g_mutex;
std::string& Component() {
  static std::string* component = new std::string("semnav");
  return *component;
}

absl::string_view LevelName(LogLevel level) {
  switch (level) {
    case LogLevel::kDebug:
      return "debug";
    case LogLevel::kInfo:
      return "info";
    case LogLevel::kWarning:
      return "warning";
    case LogLevel::kError:
      return "error";
    case LogLevel::kOff:
      return "off";
  }
  return "unknown";
}

// logfmt: bare when safe, else double-quoted with \" and \\ escaped.
void AppendValue(std::string& out, absl::string_view value) {
  const bool bare = !value.empty() && value.find_first_of(" =\"\\\n\t") == absl::string_view::npos;
  if (bare) {
    out.append(value.data(), value.size());
    return;
  }
  out.push_back('"');
  for (char c : value) {
    if (c == '"' || c == '\\') out.push_back('\\');
    if (c == '\n') {
      out.append("\\n");
      continue;
    }
    out.push_back(c);
  }
  out.push_back('"');
}

}  // namespace

void SetLogLevel(LogLevel level) { g_level = static_cast<int>(level); }
LogLevel GetLogLevel() { return static_cast<LogLevel>(g_level.load()); }

absl::StatusOr<LogLevel> ParseLogLevel(absl::string_view name) {
  const std::string lower = absl::AsciiStrToLower(name);
  for (LogLevel level :
       {LogLevel::kDebug, LogLevel::kInfo, LogLevel::kWarning, LogLevel::kError, LogLevel::kOff}) {
    if (lower == LevelName(level)) return level;
  }
  if (lower == "warn") return LogLevel::kWarning;
  return absl::InvalidArgumentError(
      absl::StrCat("log_level: '", name, "' is not one of debug, info, warning, error, off"));
}

void SetLogComponent(absl::string_view component) {
  std::lock_guard<std::mutex> lock(g_mutex);
  Component() = std::string(component);
}

std::string FormatLogLine(LogLevel level, absl::string_view event,
                          std::initializer_list<LogField> fields) {
  std::string line = absl::StrCat("level=", LevelName(level), " svc=");
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    AppendValue(line, Component());
  }
  line.append(" event=");
  AppendValue(line, event);
  for (const LogField& field : fields) {
    line.push_back(' ');
    line.append(field.key.data(), field.key.size());
    line.push_back('=');
    AppendValue(line, field.value);
  }
  return line;
}

void Log(LogLevel level, absl::string_view event, std::initializer_list<LogField> fields) {
  if (static_cast<int>(level) < g_level.load() || level == LogLevel::kOff) return;
  const std::string line = absl::StrCat(
      "ts=", absl::FormatTime("%Y-%m-%dT%H:%M:%E3SZ", absl::Now(), absl::UTCTimeZone()), " ",
      FormatLogLine(level, event, fields), "\n");
  std::fwrite(line.data(), 1, line.size(), stderr);
}

}  // namespace semnav
