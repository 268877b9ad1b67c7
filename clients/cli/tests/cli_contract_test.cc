// Contract test: the semnavctl binary as a subprocess against the five real services on
// loopback ports; checks its text and --json output and its exit codes.
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "absl/strings/str_split.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "services/reasoning/testing/table_scene_frames.h"
#include "tests/support/service_process.h"

namespace semnav::cli {
namespace {

using ::semnav::testing::ProcessResult;
using ::semnav::testing::ServiceProcess;
using ::testing::HasSubstr;

std::string Folder() {
  static const std::string dir = [] {
    const std::string path = ::testing::TempDir() + "/cli_contract";
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    return path;
  }();
  return dir;
}

std::string WriteFile(const std::string& name, const std::string& content, mode_t mode = 0600) {
  const std::string path = Folder() + "/" + name;
  std::ofstream(path) << content;
  ::chmod(path.c_str(), mode);
  return path;
}

std::unique_ptr<ServiceProcess> StartService(const std::string& binary,
                                             const std::string& config_name = "",
                                             const std::string& config = "") {
  std::vector<std::string> args;
  if (!config.empty()) args = {"--config", WriteFile(config_name, config)};
  absl::StatusOr<std::unique_ptr<ServiceProcess>> process = ServiceProcess::Start(binary, args);
  EXPECT_TRUE(process.ok()) << binary << ": " << process.status();
  return process.ok() ? *std::move(process) : nullptr;
}

// One JSON object per line of output that starts with '{'.
std::vector<nlohmann::json> JsonLines(const std::string& output) {
  std::vector<nlohmann::json> objects;
  for (absl::string_view line : absl::StrSplit(output, '\n')) {
    if (!line.empty() && line.front() == '{')
      objects.push_back(nlohmann::json::parse(std::string(line)));
  }
  return objects;
}

// Runs semnavctl with its output on a pipe until `ready` appears in it, then sends SIGINT (Ctrl-C)
// and collects the rest of the output and the exit code.
ProcessResult InterruptWhenReady(std::vector<std::string> args, const std::string& ready) {
  const std::string path = semnav::testing::BinaryPath("semnavctl");
  args.insert(args.begin(), path);
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  int out[2];
  EXPECT_EQ(::pipe(out), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(out[1], STDOUT_FILENO);
    ::dup2(out[1], STDERR_FILENO);
    ::close(out[0]);
    ::execv(path.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(out[1]);
  ProcessResult result;
  bool interrupted = false;
  char buffer[4096];
  for (;;) {
    pollfd readable{out[0], POLLIN, 0};
    if (::poll(&readable, 1, 10000) <= 0) break;  // 10 s without output: give up
    const ssize_t n = ::read(out[0], buffer, sizeof buffer);
    if (n <= 0) break;
    result.output.append(buffer, n);
    if (!interrupted && result.output.find(ready) != std::string::npos) {
      ::kill(pid, SIGINT);
      interrupted = true;
    }
  }
  ::close(out[0]);
  if (!interrupted) ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  EXPECT_TRUE(interrupted) << result.output;
  return result;
}

class CliContractTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mapping_ = StartService("semnav-mapping", "mapping.yaml",
                            "mapping:\n  store_directory: " + Folder() + "/maps\n");
    planning_ = StartService("semnav-planning", "planning.yaml",
                             "planning:\n  mapping:\n    address: " + mapping_->address() + "\n");
    relocalization_ = StartService("semnav-relocalization", "relocalization.yaml",
                                   "relocalization:\n  storage_dir: " + Folder() + "/landmarks\n");
    modelproxy_ = StartService("semnav-model-proxy");
    gateway_ = StartService("semnav-gateway", "gateway.yaml",
                            "gateway:\n  mapping:\n    address: " + mapping_->address() +
                                "\n  planning:\n    address: " + planning_->address() + "\n");
  }
  static void TearDownTestSuite() {
    gateway_.reset();
    modelproxy_.reset();
    relocalization_.reset();
    planning_.reset();
    mapping_.reset();
  }

  // semnavctl with every service's address, unless args name one already.
  static ProcessResult Ctl(std::vector<std::string> args) {
    const std::pair<std::string, std::string> addresses[] = {
        {"--gateway-addr", gateway_->address()},
        {"--mapping-addr", mapping_->address()},
        {"--planning-addr", planning_->address()},
        {"--relocalization-addr", relocalization_->address()},
        {"--modelproxy-addr", modelproxy_->address()}};
    for (const auto& [flag, address] : addresses) {
      if (std::find(args.begin(), args.end(), flag) == args.end())
        args.insert(args.end(), {flag, address});
    }
    absl::StatusOr<ProcessResult> result = semnav::testing::RunToCompletion("semnavctl", args);
    EXPECT_TRUE(result.ok()) << result.status();
    return result.ok() ? *result : ProcessResult{};
  }
  static nlohmann::json CtlJson(std::vector<std::string> args) {
    args.push_back("--json");
    const ProcessResult result = Ctl(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    std::vector<nlohmann::json> lines = JsonLines(result.output);
    EXPECT_EQ(lines.size(), 1u) << result.output;
    return lines.empty() ? nlohmann::json() : lines[0];
  }

  static inline std::unique_ptr<ServiceProcess> mapping_;
  static inline std::unique_ptr<ServiceProcess> planning_;
  static inline std::unique_ptr<ServiceProcess> relocalization_;
  static inline std::unique_ptr<ServiceProcess> modelproxy_;
  static inline std::unique_ptr<ServiceProcess> gateway_;
};

TEST_F(CliContractTest, HealthOfEveryServiceAndUnreachableExitCode) {
  const ProcessResult table = Ctl({"health"});
  EXPECT_EQ(table.exit_code, 0) << table.output;
  for (const char* name : {"gateway", "mapping", "planning", "relocalization", "modelproxy"}) {
    EXPECT_THAT(table.output, HasSubstr(name));
  }
  const nlohmann::json json = CtlJson({"health"});
  EXPECT_TRUE(json["all_serving"].get<bool>());
  ASSERT_EQ(json["services"].size(), 5u);
  for (const auto& service : json["services"]) EXPECT_EQ(service["status"], "SERVING") << service;

  // Nothing listens on port 1.
  const ProcessResult down =
      Ctl({"health", "--service", "planning", "--planning-addr", "127.0.0.1:1"});
  EXPECT_EQ(down.exit_code, 3) << down.output;
  EXPECT_THAT(down.output, HasSubstr("UNAVAILABLE"));
}

TEST_F(CliContractTest, SubmittedTaskWaitsForTheRobotAndCanBeListedWatchedAndCancelled) {
  const nlohmann::json submitted =
      CtlJson({"task", "submit", "go", "to", "the", "kitchen", "--robot", "lonely", "--no-follow"});
  const std::string task_id = submitted["task_id"];
  ASSERT_FALSE(task_id.empty());
  // No robot session: the task waits.
  EXPECT_EQ(submitted["task"]["status"], "TASK_STATUS_PENDING");
  EXPECT_EQ(submitted["task"]["instruction"], "go to the kitchen");

  const nlohmann::json listed = CtlJson({"task", "list", "--robot", "lonely"});
  ASSERT_EQ(listed["tasks"].size(), 1u) << listed;
  EXPECT_EQ(listed["tasks"][0]["task_id"], task_id);
  const ProcessResult table = Ctl({"task", "list", "--robot", "lonely"});
  EXPECT_THAT(table.output, HasSubstr("TASK"));
  EXPECT_THAT(table.output, HasSubstr(task_id + "  lonely  PENDING"));

  // Following a task that cannot start ends at the deadline with its own exit code.
  const ProcessResult watched = Ctl({"task", "watch", task_id, "--deadline", "1"});
  EXPECT_EQ(watched.exit_code, 4) << watched.output;
  EXPECT_THAT(watched.output, HasSubstr(task_id + "  PENDING"));
  EXPECT_THAT(watched.output, HasSubstr("DEADLINE_EXCEEDED"));

  const ProcessResult cancelled = Ctl({"task", "cancel", task_id, "--reason", "test over"});
  EXPECT_EQ(cancelled.exit_code, 0) << cancelled.output;
  EXPECT_THAT(cancelled.output, HasSubstr("CANCELLED"));
  EXPECT_EQ(CtlJson({"task", "get", task_id})["task"]["status"], "TASK_STATUS_CANCELLED");
  EXPECT_EQ(CtlJson({"task", "list", "--robot", "lonely", "--unfinished"})["tasks"].size(), 0u);
  // Watching a finished task prints its final state and exits with the task's outcome.
  const ProcessResult rewatched = Ctl({"task", "watch", task_id});
  EXPECT_EQ(rewatched.exit_code, 11) << rewatched.output;
  EXPECT_THAT(rewatched.output, HasSubstr("CANCELLED"));
  // Control calls on a finished task are refused as a failed precondition naming the task.
  const ProcessResult paused = Ctl({"task", "pause", task_id});
  EXPECT_EQ(paused.exit_code, 7) << paused.output;
  EXPECT_THAT(paused.output,
              HasSubstr("FAILED_PRECONDITION: task_id: task " + task_id + " already finished"));
}

TEST_F(CliContractTest, CtrlCDetachesFromAFollowedTaskWhichGoesOn) {
  std::vector<std::string> args = {
      "task", "submit", "wait", "--robot", "detach", "--gateway-addr", gateway_->address()};
  const ProcessResult detached = InterruptWhenReady(args, "PENDING");
  EXPECT_EQ(detached.exit_code, 0) << detached.output;
  EXPECT_THAT(detached.output, HasSubstr("detached; the task goes on"));
  const nlohmann::json listed = CtlJson({"task", "list", "--robot", "detach", "--unfinished"});
  ASSERT_EQ(listed["tasks"].size(), 1u) << listed;
  EXPECT_EQ(listed["tasks"][0]["status"], "TASK_STATUS_PENDING");
  // Ctrl-C ends an event watch cleanly too (a second task makes sure events follow id 1).
  ASSERT_EQ(Ctl({"task", "submit", "look", "around", "--robot", "detach", "--no-follow"}).exit_code,
            0);
  const ProcessResult stopped =
      InterruptWhenReady({"events", "watch", "--gateway-addr", gateway_->address(), "--robot",
                          "detach", "--since", "1"},
                         "TASK_CREATED");
  EXPECT_EQ(stopped.exit_code, 0) << stopped.output;
}

TEST_F(CliContractTest, TypedErrorExitCodes) {
  const ProcessResult unknown = Ctl({"task", "get", "task-999999"});
  EXPECT_EQ(unknown.exit_code, 5) << unknown.output;
  EXPECT_THAT(unknown.output, HasSubstr("NOT_FOUND"));
  const ProcessResult empty = Ctl({"task", "submit", "", "--robot", "r1", "--no-follow"});
  EXPECT_EQ(empty.exit_code, 6) << empty.output;
  EXPECT_THAT(empty.output, HasSubstr("instruction"));
  EXPECT_EQ(Ctl({"task", "frobnicate"}).exit_code, 2);
  EXPECT_EQ(Ctl({"task", "get"}).exit_code, 2);
  EXPECT_EQ(Ctl({"task", "list", "--bogus"}).exit_code, 2);
  const ProcessResult bad_point = Ctl({"plan", "path", "--from", "1", "--to", "2,2"});
  EXPECT_EQ(bad_point.exit_code, 2);
  EXPECT_THAT(bad_point.output, HasSubstr("--from: '1' is not a point X,Y in metres"));
  EXPECT_EQ(Ctl({"map", "load", "no-such-map"}).exit_code, 5);
  const ProcessResult help = Ctl({"plan", "path", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.output, HasSubstr("--planner NAME"));
  EXPECT_THAT(help.output, HasSubstr("Exit codes:"));
}

TEST_F(CliContractTest, LeaseAndEmergencyStop) {
  const nlohmann::json lease =
      CtlJson({"lease", "acquire", "--robot", "r2", "--holder", "alice", "--ttl", "60"});
  const std::string lease_id = lease["lease"]["lease_id"];
  ASSERT_FALSE(lease_id.empty());
  EXPECT_EQ(Ctl({"lease", "acquire", "--robot", "r2", "--holder", "bob"}).exit_code, 7);
  // The robot's lease is held: submitting without it is refused, with it accepted.
  EXPECT_EQ(Ctl({"task", "submit", "wait", "--robot", "r2", "--no-follow"}).exit_code, 7);
  const nlohmann::json submitted = CtlJson(
      {"task", "submit", "look", "around", "--robot", "r2", "--lease", lease_id, "--no-follow"});
  const std::string task_id = submitted["task_id"];

  const nlohmann::json stopped =
      CtlJson({"estop", "trigger", "--robot", "r2", "--reason", "drill"});
  EXPECT_THAT(stopped["cancelled_task_ids"].get<std::vector<std::string>>(),
              ::testing::Contains(task_id));
  EXPECT_EQ(CtlJson({"task", "get", task_id})["task"]["status"], "TASK_STATUS_CANCELLED");
  const ProcessResult refused =
      Ctl({"task", "submit", "wait", "--robot", "r2", "--lease", lease_id, "--no-follow"});
  EXPECT_EQ(refused.exit_code, 7) << refused.output;
  EXPECT_EQ(Ctl({"estop", "clear", "--robot", "r2", "--lease", lease_id}).exit_code, 0);
  EXPECT_EQ(Ctl({"task", "submit", "wait", "--robot", "r2", "--lease", lease_id, "--no-follow"})
                .exit_code,
            0);
  EXPECT_EQ(Ctl({"lease", "release", lease_id}).exit_code, 0);
  EXPECT_EQ(Ctl({"lease", "acquire", "--robot", "r2", "--holder", "bob"}).exit_code, 0);
}

TEST_F(CliContractTest, EventsReplayAfterAnId) {
  for (const char* text : {"wait", "look around"}) {
    ASSERT_EQ(Ctl({"task", "submit", text, "--robot", "ev", "--no-follow"}).exit_code, 0);
  }
  const ProcessResult replay =
      Ctl({"events", "watch", "--robot", "ev", "--since", "1", "--count", "2", "--json"});
  EXPECT_EQ(replay.exit_code, 0) << replay.output;
  const std::vector<nlohmann::json> events = JsonLines(replay.output);
  ASSERT_EQ(events.size(), 2u) << replay.output;
  // uint64 ids travel as JSON strings.
  const uint64_t first = std::stoull(events[0]["event"]["event_id"].get<std::string>());
  EXPECT_GT(first, 1u);
  EXPECT_GT(std::stoull(events[1]["event"]["event_id"].get<std::string>()), first);
  for (const auto& event : events) EXPECT_EQ(event["event"]["robot_id"], "ev") << event;
  const ProcessResult text =
      Ctl({"events", "watch", "--robot", "ev", "--since", "1", "--count", "1"});
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("robot=ev"));
}

TEST_F(CliContractTest, SceneGraphTableMapsAndPlanOnTheLiveMap) {
  ASSERT_TRUE(reasoning::testing::StreamTableFrames(mapping_->channel(), 1, 6).ok());
  const ProcessResult table = Ctl({"scene", "show"});
  EXPECT_EQ(table.exit_code, 0) << table.output;
  EXPECT_THAT(table.output, HasSubstr("LABEL"));
  EXPECT_THAT(table.output, HasSubstr("table"));
  const nlohmann::json graph = CtlJson({"scene", "show"});
  ASSERT_GE(graph["graph"]["objects"].size(), 1u) << graph;
  EXPECT_EQ(graph["graph"]["objects"][0]["label"], "table");

  EXPECT_EQ(Ctl({"map", "save", "lab"}).exit_code, 0);
  const nlohmann::json maps = CtlJson({"map", "list"});
  ASSERT_EQ(maps["maps"].size(), 1u) << maps;
  EXPECT_EQ(maps["maps"][0]["map_id"], "lab");
  EXPECT_THAT(Ctl({"map", "list"}).output, HasSubstr("lab"));
  EXPECT_EQ(Ctl({"map", "load", "lab"}).exit_code, 0);

  // The planner fetches mapping's live grid; the robot's viewpoint side of the room is observed.
  const nlohmann::json path = CtlJson({"plan", "path", "--from", "1.5,1.3", "--to", "2.2,1.3"});
  EXPECT_GT(path["length_m"].get<double>(), 0.6) << path;
  EXPECT_GT(std::stoull(path["map_revision"].get<std::string>()), 0u) << path;
}

TEST_F(CliContractTest, PlanOnATextGridPrintsLengthAndRollFlySplit) {
  // A wall in the middle row: the 2D planner goes round it, 1 + 4 + 1 = 6 cells.
  const std::string wall = WriteFile("wall.txt", ".....\n.###.\n.....\n");
  const nlohmann::json around = CtlJson({"plan", "path", "--grid", wall, "--planner", "astar",
                                         "--from", "0.5,1.5", "--to", "4.5,1.5"});
  EXPECT_DOUBLE_EQ(around["length_m"].get<double>(), 6.0) << around;
  const ProcessResult text = Ctl({"plan", "path", "--grid", wall, "--planner", "astar", "--from",
                                  "0.5,1.5", "--to", "4.5,1.5"});
  EXPECT_THAT(text.output, HasSubstr("length 6.00 m  (roll 6.00 m, fly 0.00 m"));

  // One corridor with a low obstacle: jump-astar must fly over it.
  const std::string corridor = WriteFile("corridor.txt", "..2..\n");
  const nlohmann::json over = CtlJson({"plan", "path", "--grid", corridor, "--planner",
                                       "jump-astar", "--from", "0.5,0.5", "--to", "4.5,0.5"});
  EXPECT_GT(over["fly_m"].get<double>(), 0.0) << over;
  EXPECT_NEAR(over["fly_m"].get<double>() + over["roll_m"].get<double>(),
              over["length_m"].get<double>(), 1e-9);
  EXPECT_GT(over["energy_j"].get<double>(), 0.0);
  EXPECT_THAT(Ctl({"plan", "path", "--grid", corridor, "--planner", "jump-astar", "--from",
                   "0.5,0.5", "--to", "4.5,0.5"})
                  .output,
              HasSubstr("FLYING"));

  // The goal is walled in: NOT_FOUND with the planner's reason.
  const std::string closed = WriteFile("closed.txt", "..#..\n..#..\n");
  const ProcessResult no_path =
      Ctl({"plan", "path", "--grid", closed, "--from", "0.5,0.5", "--to", "4.5,0.5"});
  EXPECT_EQ(no_path.exit_code, 5) << no_path.output;
  EXPECT_THAT(no_path.output, HasSubstr("NO_PATH"));
}

TEST_F(CliContractTest, RelocalizeObservedLandmarksInALandmarkMap) {
  // Six objects with distinct one-hot descriptors; the robot sees them shifted by (-1, -2, 0).
  const double positions[6][3] = {{0, 0, 0.5}, {3, 0, 0.8},   {0, 4, 0.4},
                                  {3, 4, 1.2}, {1.5, 2, 0.3}, {5, 1, 0.9}};
  nlohmann::json landmarks = nlohmann::json::array();
  nlohmann::json observed = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) {
    std::vector<float> embedding(6, 0.0f);
    embedding[i] = 1.0f;
    landmarks.push_back(
        {{"position", {{"x", positions[i][0]}, {"y", positions[i][1]}, {"z", positions[i][2]}}},
         {"scale_m", 0.5 + 0.1 * i},
         {"embedding", embedding}});
    observed.push_back(
        {{"position",
          {{"x", positions[i][0] - 1}, {"y", positions[i][1] - 2}, {"z", positions[i][2]}}},
         {"scale_m", 0.5 + 0.1 * i},
         {"embedding", embedding}});
  }
  const std::string map_file =
      WriteFile("landmarks.json", nlohmann::json{{"landmarks", landmarks}}.dump());
  const std::string observed_file =
      WriteFile("observed.json", nlohmann::json{{"observed", observed}}.dump());
  EXPECT_EQ(CtlJson({"reloc", "upsert", "--map-id", "office", "--landmarks", map_file})["inserted"],
            6);
  EXPECT_THAT(Ctl({"reloc", "show", "--map-id", "office"}).output, HasSubstr("6 landmarks"));

  const nlohmann::json pose =
      CtlJson({"reloc", "relocalize", "--map-id", "office", "--observed", observed_file});
  const nlohmann::json& position = pose["solution"]["map_from_query"]["position"];
  EXPECT_NEAR(position["x"].get<double>(), 1.0, 1e-3) << pose;
  EXPECT_NEAR(position["y"].get<double>(), 2.0, 1e-3) << pose;
  EXPECT_GE(pose["solution"]["inlier_count"].get<int>(), 3);
  EXPECT_THAT(
      Ctl({"reloc", "relocalize", "--map-id", "office", "--observed", observed_file}).output,
      HasSubstr("translation (1.000, 2.000, 0.000) m"));
  EXPECT_EQ(
      Ctl({"reloc", "relocalize", "--map-id", "nowhere", "--observed", observed_file}).exit_code,
      5);
}

// semnavctl health of one service at `address` with extra flags, without the suite's addresses.
ProcessResult HealthOf(const std::string& address, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"health", "--service", "relocalization", "--relocalization-addr",
                                   address};
  args.insert(args.end(), extra.begin(), extra.end());
  absl::StatusOr<ProcessResult> result = semnav::testing::RunToCompletion("semnavctl", args);
  EXPECT_TRUE(result.ok()) << result.status();
  return result.ok() ? *result : ProcessResult{};
}

std::unique_ptr<ServiceProcess> StartSecured(const std::string& config_name,
                                             const std::string& config) {
  absl::StatusOr<std::unique_ptr<ServiceProcess>> process = ServiceProcess::Start(
      "semnav-relocalization", {"--config", WriteFile(config_name, config)}, absl::Seconds(20),
      /*wait_for_health=*/false);
  EXPECT_TRUE(process.ok()) << process.status();
  return process.ok() ? *std::move(process) : nullptr;
}

TEST_F(CliContractTest, TlsServiceNeedsTheCa) {
  const std::string key = Folder() + "/server.key";
  const std::string cert = Folder() + "/server.crt";
  const std::string command =
      "openssl req -x509 -newkey rsa:2048 -nodes -days 2 -subj /CN=localhost -addext "
      "subjectAltName=DNS:localhost,IP:127.0.0.1 -keyout " +
      key + " -out " + cert + " 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << "openssl is needed (deploy/install-deps.sh)";
  std::unique_ptr<ServiceProcess> secured = StartSecured(
      "tls.yaml", "server:\n  tls:\n    cert_file: " + cert + "\n    key_file: " + key + "\n");
  ASSERT_NE(secured, nullptr);
  const ProcessResult verified = HealthOf(secured->address(), {"--tls-ca", cert});
  EXPECT_EQ(verified.exit_code, 0) << verified.output;
  EXPECT_THAT(verified.output, HasSubstr("SERVING"));
  EXPECT_EQ(HealthOf(secured->address(), {}).exit_code, 3);  // plaintext to a TLS port
  EXPECT_EQ(HealthOf(secured->address(), {"--tls-ca", Folder() + "/missing.pem"}).exit_code, 2);
  EXPECT_EQ(HealthOf(secured->address(), {"--tls-cert", cert}).exit_code, 2);  // without --tls-key
}

TEST_F(CliContractTest, TokenFromFileOrEnvironmentReachesASecuredService) {
  const std::string tokens = WriteFile("tokens", "cli-token\n");
  std::unique_ptr<ServiceProcess> secured =
      StartSecured("secured.yaml", "server:\n  auth:\n    token_file: " + tokens + "\n");
  ASSERT_NE(secured, nullptr);
  EXPECT_EQ(HealthOf(secured->address(), {}).exit_code, 8);
  EXPECT_EQ(HealthOf(secured->address(), {"--token-file", tokens}).exit_code, 0);
  ::setenv("CLI_TEST_TOKEN", "cli-token", 1);
  EXPECT_EQ(HealthOf(secured->address(), {"--token-env", "CLI_TEST_TOKEN"}).exit_code, 0);
  ::setenv("CLI_TEST_TOKEN", "wrong-token", 1);
  const ProcessResult wrong = HealthOf(secured->address(), {"--token-env", "CLI_TEST_TOKEN"});
  EXPECT_EQ(wrong.exit_code, 8) << wrong.output;
  EXPECT_THAT(wrong.output, HasSubstr("UNAUTHENTICATED"));
}

}  // namespace
}  // namespace semnav::cli
