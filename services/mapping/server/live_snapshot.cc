#include "services/mapping/server/live_snapshot.h"

#include <filesystem>

#include "services/common/logging/log.h"

namespace semnav::mapping {
namespace {

constexpr char kSnapshotId[] = "snapshot";

}  // namespace

absl::StatusOr<std::unique_ptr<LiveSnapshot>> LiveSnapshot::Start(
    MappingEngine& engine, const std::string& store_directory, absl::Duration interval) {
  absl::StatusOr<MapStore> store =
      MapStore::Open((std::filesystem::path(store_directory) / "live").string());
  if (!store.ok()) return store.status();
  std::unique_ptr<LiveSnapshot> snapshot(new LiveSnapshot(engine, *std::move(store), interval));
  absl::StatusOr<std::string> left = snapshot->store_.Load(kSnapshotId);
  if (left.ok()) {
    if (absl::Status restored = engine.Restore(*left); restored.ok()) {
      snapshot->restored_revision_ = snapshot->saved_revision_ = engine.revision();
      LogInfo("live_map_restored", {{"revision", static_cast<int64_t>(engine.revision())}});
    } else {
      LogWarning("live_map_snapshot_unreadable", {{"message", restored.message()}});
    }
  } else if (!absl::IsNotFound(left.status())) {
    LogWarning("live_map_snapshot_unreadable", {{"message", left.status().message()}});
  }
  snapshot->thread_ = std::thread([raw = snapshot.get()] { raw->Run(); });
  return snapshot;
}

LiveSnapshot::~LiveSnapshot() { Stop(); }

void LiveSnapshot::Run() {
  absl::MutexLock lock(&mu_);
  while (!stopping_) {
    mu_.AwaitWithTimeout(absl::Condition(&stopping_), interval_);
    if (stopping_) break;
    const uint64_t revision = engine_.revision();
    if (revision == saved_revision_) continue;
    mu_.Unlock();  // serialising a large map must not hold up Stop()
    const absl::StatusOr<StoredMap> saved = store_.Save(kSnapshotId, engine_.Serialize());
    mu_.Lock();
    if (saved.ok()) {
      saved_revision_ = revision;
    } else {
      LogWarning("live_map_snapshot_failed", {{"message", saved.status().message()}});
    }
  }
}

void LiveSnapshot::Stop() {
  {
    absl::MutexLock lock(&mu_);
    stopping_ = true;
  }
  if (thread_.joinable()) thread_.join();
}

void LiveSnapshot::StopAndDiscard() {
  Stop();
  if (absl::Status removed = store_.Delete(kSnapshotId);
      !removed.ok() && !absl::IsNotFound(removed)) {
    LogWarning("live_map_snapshot_not_removed", {{"message", removed.message()}});
  }
}

}  // namespace semnav::mapping
