// The one-line task progress shown while following a task, and the printer that keeps it live on
// a terminal (rewritten in place) or appends a line per change when output is a pipe or file.
#pragma once

#include <ostream>
#include <string>

namespace semnav::cli {

// What the line shows, in display form (enum names already shortened).
struct TaskProgress {
  std::string task_id;
  std::string status;       // e.g. "RUNNING"
  double progress = 0.0;    // [0, 1]
  int current_subgoal = 0;  // 0-based index; == subgoal_count when done
  int subgoal_count = 0;
  std::string step;    // active subgoal, e.g. "FIND cup"; empty when done
  std::string phase;   // e.g. "exploring"; empty before start
  std::string reason;  // latest decision or failure reason
};

// "task-3  RUNNING    [######--------------]  30%  step 2/5 FIND cup  exploring  -- reason".
std::string FormatProgressLine(const TaskProgress& progress, int bar_width = 20);

class ProgressPrinter {
 public:
  // `live`: rewrite one terminal line in place; otherwise print each changed line once.
  ProgressPrinter(std::ostream& out, bool live) : out_(out), live_(live) {}
  void Show(const std::string& line);
  // Ends the live line with a newline (no-op when nothing was shown).
  void Finish();

 private:
  std::ostream& out_;
  bool live_;
  std::string last_;
  bool shown_ = false;
};

}  // namespace semnav::cli
