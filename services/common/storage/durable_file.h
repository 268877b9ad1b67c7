// Files that survive a crash: written whole or not at all, and read back only if intact.
// One implementation for every store that must not lose or half-write state (saved maps, the
// live-map snapshot, landmark maps, the gateway's task journal, the launcher's stack state).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace semnav::storage {

// Replaces `path` atomically: the bytes go to a temporary file in the same directory, which is
// fsynced and renamed over `path`, then the directory is fsynced. A crash at any point leaves
// either the old file or the new one. The temporary file is removed on failure.
absl::Status WriteFileAtomically(const std::string& path, absl::string_view bytes);
// The same for a file made of `pieces` in order, written one after the other without joining
// them (a large map is not copied once more to be written).
absl::Status WriteFileAtomically(const std::string& path,
                                 std::initializer_list<absl::string_view> pieces);

// Removes `path` and fsyncs its directory, so the removal survives a crash; NOT_FOUND when absent.
absl::Status RemoveFileDurably(const std::string& path);

// The whole file; NOT_FOUND when it does not exist.
absl::StatusOr<std::string> ReadWholeFile(const std::string& path);

// CRC-32 (IEEE 802.3, the zlib/PNG polynomial).
uint32_t Crc32(absl::string_view data);

// The checksummed frame: `magic`, the payload size (8 bytes, little-endian), its CRC-32
// (4 bytes, little-endian), then the payload.
std::string FrameWithChecksum(absl::string_view magic, absl::string_view payload);
// The frame's header alone (magic, size, CRC-32): the frame is this followed by the payload.
std::string FrameHeader(absl::string_view magic, absl::string_view payload);
// WriteFileAtomically of FrameWithChecksum(magic, payload), without building the frame in memory.
absl::Status WriteFramedFileAtomically(const std::string& path, absl::string_view magic,
                                       absl::string_view payload);
// The payload of a frame; DATA_LOSS naming `what` when the magic, size or checksum is wrong.
absl::StatusOr<std::string> PayloadOfFrame(absl::string_view magic, absl::string_view file,
                                           absl::string_view what);

}  // namespace semnav::storage
