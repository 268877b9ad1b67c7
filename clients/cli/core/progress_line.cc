#include "clients/cli/core/progress_line.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace semnav::cli {

std::string FormatProgressLine(const TaskProgress& progress, int bar_width) {
  const double fraction = std::clamp(progress.progress, 0.0, 1.0);
  const int filled = static_cast<int>(std::lround(fraction * bar_width));
  std::string line = absl::StrFormat("%s  %-9s  [%s%s]  %3d%%", progress.task_id, progress.status,
                                     std::string(filled, '#'), std::string(bar_width - filled, '-'),
                                     static_cast<int>(std::lround(fraction * 100.0)));
  if (progress.subgoal_count > 0) {
    const int shown_step = std::min(progress.current_subgoal + 1, progress.subgoal_count);
    absl::StrAppend(&line, "  step ", shown_step, "/", progress.subgoal_count);
    if (!progress.step.empty()) absl::StrAppend(&line, " ", progress.step);
  }
  if (!progress.phase.empty()) absl::StrAppend(&line, "  ", progress.phase);
  if (!progress.reason.empty()) absl::StrAppend(&line, "  -- ", progress.reason);
  return line;
}

void ProgressPrinter::Show(const std::string& line) {
  if (shown_ && line == last_) return;
  if (live_) {
    out_ << "\r\033[K" << line << std::flush;  // carriage return + clear to end of line
  } else {
    out_ << line << "\n" << std::flush;
  }
  last_ = line;
  shown_ = true;
}

void ProgressPrinter::Finish() {
  if (live_ && shown_) out_ << "\n" << std::flush;
  shown_ = false;
}

}  // namespace semnav::cli
