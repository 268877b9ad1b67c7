#include "services/reasoning/core/gateway_journal.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "services/common/storage/durable_file.h"

namespace semnav::reasoning {
namespace {

std::string FreshDirectory(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / ("journal_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

JournaledTask FindCupTask() {
  JournaledTask t;
  t.task_id = "task-7";
  t.robot_id = "go2";
  t.instruction = "去厨房找红色杯子";
  t.source = "rules";
  t.strategy = ExplorationStrategy::kSemanticFrontier;
  t.search_area = SearchArea{{-1.0, -2.0}, {8.5, 6.0}};
  Subgoal kitchen;
  kitchen.type = SubgoalType::kNavigate;
  kitchen.target.name = "kitchen";
  kitchen.target.is_room = true;
  Subgoal cup;
  cup.type = SubgoalType::kFind;
  cup.target.name = "cup";
  cup.target.colours = {"red"};
  cup.target.text = "红色杯子";
  cup.reason = "the object asked for";
  t.subgoals = {kitchen, cup};
  t.progress.state = TaskState::kRunning;
  t.progress.subgoal_index = 1;
  t.progress.phase = "exploring";
  t.progress.reason = "exploration goal 3";
  t.progress.replans = 2;
  t.progress.explore_goals = 3;
  t.progress.model_requests = 1;
  t.model_calls = 4;
  t.created = absl::FromUnixSeconds(1'700'000'000);
  t.updated = absl::FromUnixSeconds(1'700'000'042);
  return t;
}

LoggedEvent Event(uint64_t id, std::string message) {
  return LoggedEvent{id,       absl::FromUnixSeconds(1'700'000'000 + static_cast<int64_t>(id)),
                     3,        "go2",
                     "task-7", std::move(message)};
}

TEST(GatewayJournalTest, StateRoundTripsEveryField) {
  GatewayState state;
  state.next_task = 8;
  state.tasks = {FindCupTask()};
  state.leases = {LeaseInfo{"lease-1", "go2", "tablet", absl::FromUnixSeconds(1'700'000'100)}};
  const absl::StatusOr<GatewayState> back = DecodeGatewayState(EncodeGatewayState(state));
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->next_task, 8u);
  ASSERT_EQ(back->tasks.size(), 1u);
  const JournaledTask& t = back->tasks[0];
  const JournaledTask want = FindCupTask();
  EXPECT_EQ(t.instruction, want.instruction);
  EXPECT_EQ(t.subgoals, want.subgoals);
  EXPECT_EQ(t.progress.state, TaskState::kRunning);
  EXPECT_EQ(t.progress.subgoal_index, 1);
  EXPECT_EQ(t.progress.phase, "exploring");
  EXPECT_EQ(t.progress.explore_goals, 3);
  EXPECT_EQ(t.model_calls, 4);
  EXPECT_EQ(t.created, want.created);
  EXPECT_EQ(t.updated, want.updated);
  ASSERT_TRUE(t.search_area.has_value());
  EXPECT_EQ(t.search_area->max, Eigen::Vector2d(8.5, 6.0));
  ASSERT_EQ(back->leases.size(), 1u);
  EXPECT_EQ(back->leases[0].holder, "tablet");
  EXPECT_EQ(back->leases[0].expires_at, absl::FromUnixSeconds(1'700'000'100));
}

TEST(GatewayJournalTest, DecodeNamesTheBadField) {
  GatewayState state;
  state.tasks = {FindCupTask()};
  std::string text = EncodeGatewayState(state);
  text.replace(text.find("\"FIND\""), 6, "\"FLY\"");
  EXPECT_EQ(DecodeGatewayState(text).status().message(),
            "gateway journal: tasks[0].subgoals[1].type is unknown");
  state.tasks[0].progress.subgoal_index = 2;  // past the end
  EXPECT_EQ(DecodeGatewayState(EncodeGatewayState(state)).status().message(),
            "gateway journal: tasks[0].subgoal_index is out of range");
  EXPECT_TRUE(absl::IsDataLoss(DecodeGatewayState("[1,2]").status()));
  EXPECT_TRUE(absl::IsDataLoss(
      DecodeGatewayState(R"({"version":1,"next_task":"x","tasks":[],"leases":[]})").status()));
}

TEST(GatewayJournalTest, EventLinesCarryAChecksum) {
  const std::string line = EncodeEventLine(Event(5, "TASK_STATUS_PAUSED: dependency_unavailable"));
  ASSERT_EQ(line.back(), '\n');
  const std::optional<LoggedEvent> back = DecodeEventLine(line);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->id, 5u);
  EXPECT_EQ(back->message, "TASK_STATUS_PAUSED: dependency_unavailable");
  std::string damaged = line;
  damaged[damaged.size() - 4] ^= 0x01;
  EXPECT_FALSE(DecodeEventLine(damaged).has_value());
  EXPECT_FALSE(DecodeEventLine(line.substr(0, line.size() / 2)).has_value());  // torn write
}

TEST(GatewayJournalTest, RecoversStateAndTheRetainedEvents) {
  const std::string dir = FreshDirectory("recover");
  {
    GatewayJournal journal = *GatewayJournal::Open(dir, 3);
    GatewayState state;
    state.next_task = 8;
    state.tasks = {FindCupTask()};
    ASSERT_TRUE(journal.SaveState(state).ok());
    ASSERT_TRUE(journal.AppendEvents({Event(1, "a"), Event(2, "b")}).ok());
    ASSERT_TRUE(journal.AppendEvents({Event(3, "c"), Event(4, "d")}).ok());
  }
  GatewayJournal journal = *GatewayJournal::Open(dir, 3);
  const absl::StatusOr<GatewayJournal::Recovered> recovered = journal.Recover();
  ASSERT_TRUE(recovered.ok()) << recovered.status();
  EXPECT_EQ(recovered->state.next_task, 8u);
  ASSERT_EQ(recovered->state.tasks.size(), 1u);
  ASSERT_EQ(recovered->events.size(), 3u);  // the newest 3 of 4
  EXPECT_EQ(recovered->events.front().message, "b");
  EXPECT_EQ(recovered->events.back().message, "d");
  EXPECT_EQ(recovered->damaged_event_lines, 0);
}

TEST(GatewayJournalTest, ATornLastEventIsSkippedAndTheRestKept) {
  const std::string dir = FreshDirectory("torn");
  GatewayJournal journal = *GatewayJournal::Open(dir, 10);
  ASSERT_TRUE(journal.AppendEvents({Event(1, "a"), Event(2, "b")}).ok());
  {
    std::ofstream out(journal.events_path(), std::ios::app);
    out << EncodeEventLine(Event(3, "c")).substr(0, 20);  // the process died mid-write
  }
  const absl::StatusOr<GatewayJournal::Recovered> recovered = journal.Recover();
  ASSERT_TRUE(recovered.ok());
  ASSERT_EQ(recovered->events.size(), 2u);
  EXPECT_EQ(recovered->damaged_event_lines, 1);
  EXPECT_TRUE(recovered->state.tasks.empty());  // no state file yet: a fresh gateway
  // Recovery compacted the log: the torn line is gone.
  EXPECT_EQ(*storage::ReadWholeFile(journal.events_path()),
            EncodeEventLine(Event(1, "a")) + EncodeEventLine(Event(2, "b")));
}

TEST(GatewayJournalTest, ADamagedStateFileIsDataLoss) {
  const std::string dir = FreshDirectory("damaged");
  GatewayJournal journal = *GatewayJournal::Open(dir, 10);
  GatewayState state;
  state.tasks = {FindCupTask()};
  ASSERT_TRUE(journal.SaveState(state).ok());
  std::string bytes = *storage::ReadWholeFile(journal.state_path());
  bytes[bytes.size() / 2] ^= 0x20;
  ASSERT_TRUE(storage::WriteFileAtomically(journal.state_path(), bytes).ok());
  EXPECT_THAT(std::string(journal.Recover().status().message()),
              ::testing::HasSubstr("fails its checksum"));
}

TEST(GatewayJournalTest, TheEventLogIsCompactedAtTwiceTheRetainedCount) {
  const std::string dir = FreshDirectory("compact");
  GatewayJournal journal = *GatewayJournal::Open(dir, 2);
  for (uint64_t id = 1; id <= 5; ++id) ASSERT_TRUE(journal.AppendEvents({Event(id, "e")}).ok());
  // After the 5th line (> 2 x 2) the file holds only the newest 2.
  EXPECT_EQ(*storage::ReadWholeFile(journal.events_path()),
            EncodeEventLine(Event(4, "e")) + EncodeEventLine(Event(5, "e")));
}

}  // namespace
}  // namespace semnav::reasoning
