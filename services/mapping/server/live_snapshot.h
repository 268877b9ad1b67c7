#pragma once

#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "services/mapping/core/map_store.h"
#include "services/mapping/core/mapping_engine.h"

namespace semnav::mapping {

// Crash recovery of the live map. Every `interval`, if the map changed, it is written to
// <store>/live/snapshot.snmap through MapStore (temp file, fsync, rename, CRC-32). A clean
// shutdown removes the snapshot, so only a process that died finds it at its next start, and
// restores it: a service that `semnav up` restarts after a crash keeps its map, while a stack
// started afresh begins with an empty one.
class LiveSnapshot {
 public:
  // Restores a snapshot left by a crash into `engine` (a corrupt one is logged and dropped), then
  // snapshots in a background thread. `engine` must outlive the returned object.
  static absl::StatusOr<std::unique_ptr<LiveSnapshot>> Start(MappingEngine& engine,
                                                             const std::string& store_directory,
                                                             absl::Duration interval);
  ~LiveSnapshot();

  // Revision of the map restored at start, if any.
  std::optional<uint64_t> restored_revision() const { return restored_revision_; }
  // Clean shutdown: stop snapshotting and remove the snapshot.
  void StopAndDiscard();

 private:
  LiveSnapshot(MappingEngine& engine, MapStore store, absl::Duration interval)
      : engine_(engine), store_(std::move(store)), interval_(interval) {}
  void Run();
  void Stop();

  MappingEngine& engine_;
  MapStore store_;
  absl::Duration interval_;
  std::optional<uint64_t> restored_revision_;
  uint64_t saved_revision_ = 0;
  absl::Mutex mu_;
  bool stopping_ ABSL_GUARDED_BY(mu_) = false;
  std::thread thread_;
};

}  // namespace semnav::mapping
