#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::launcher {

// Starts argv[0] with `argv` as a child that dies with its parent: PR_SET_PDEATHSIG delivers
// SIGTERM when the launcher exits, even by SIGKILL, so no service outlives `semnav up`. The
// child gets its own process group (Ctrl-C reaches only the launcher, which stops children in
// order) and an empty signal mask. With `output_file`, the child's stdout goes there.
absl::StatusOr<pid_t> SpawnChild(const std::vector<std::string>& argv,
                                 const std::string& output_file = "");

// A program found on PATH ("" if none), e.g. FindOnPath("node").
std::string FindOnPath(const std::string& program);

// "exit code 3", "killed by signal 9 (Killed)": a waitpid status for people.
std::string DescribeExit(int wait_status);

}  // namespace semnav::launcher
