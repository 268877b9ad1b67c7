// Display forms of the gateway's task snapshots: progress line fields, detail text and rows.
#pragma once

#include <string>

#include "clients/cli/core/exit_codes.h"
#include "clients/cli/core/progress_line.h"
#include "semnav/reasoning/v1/task.pb.h"

namespace semnav::cli {

namespace reasoning_api = ::semnav::reasoning::v1;

TaskProgress ToProgress(const reasoning_api::TaskSnapshot& task);
// "RUNNING" for TASK_STATUS_RUNNING.
std::string StatusName(reasoning_api::TaskStatus status);
// "FIND red cup" for a subgoal.
std::string SubgoalLabel(const reasoning_api::Subgoal& subgoal);
bool IsFinished(reasoning_api::TaskStatus status);
// Exit code of a followed task that reached `status`.
ExitCode ExitCodeForTask(reasoning_api::TaskStatus status);
// Multi-line description: header, subgoals table, resolved target.
std::string DescribeTask(const reasoning_api::TaskSnapshot& task);

}  // namespace semnav::cli
