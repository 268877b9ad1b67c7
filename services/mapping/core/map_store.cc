#include "services/mapping/core/map_store.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"

namespace semnav::mapping {
namespace {

constexpr char kMagic[] = "SNMAP1\n";
constexpr size_t kMagicSize = sizeof(kMagic) - 1;
constexpr size_t kHeaderSize = kMagicSize + 8 + 4;
constexpr char kSuffix[] = ".snmap";

std::array<uint32_t, 256> MakeCrcTable() {
  std::array<uint32_t, 256> table{};
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[i] = c;
  }
  return table;
}

void PutLe(std::string& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

uint64_t GetLe(const std::string& in, size_t offset, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= static_cast<uint64_t>(static_cast<unsigned char>(in[offset + i])) << (8 * i);
  return value;
}

absl::Status ErrnoStatus(absl::string_view what, const std::string& path) {
  return absl::InternalError(absl::StrCat(what, " ", path, ": ", std::strerror(errno)));
}

// Writes all of `data` to a new file and fsyncs it.
absl::Status WriteDurably(const std::string& path, const std::string& data) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return ErrnoStatus("open", path);
  size_t written = 0;
  while (written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const absl::Status status = ErrnoStatus("write", path);
      ::close(fd);
      return status;
    }
    written += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const absl::Status status = ErrnoStatus("fsync", path);
    ::close(fd);
    return status;
  }
  if (::close(fd) != 0) return ErrnoStatus("close", path);
  return absl::OkStatus();
}

absl::Status SyncDirectory(const std::string& directory) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return ErrnoStatus("open", directory);
  const int rc = ::fsync(fd);
  ::close(fd);
  return rc == 0 ? absl::OkStatus() : ErrnoStatus("fsync", directory);
}

}  // namespace

uint32_t Crc32(const std::string& data) {
  static const std::array<uint32_t, 256> table = MakeCrcTable();
  uint32_t c = 0xFFFFFFFFu;
  for (unsigned char byte : data) c = table[(c ^ byte) & 0xff] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

absl::Status MapStore::ValidateMapId(const std::string& map_id) {
  const bool ok = !map_id.empty() && map_id.size() <= 64 && std::all_of(map_id.begin(), map_id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  if (ok) return absl::OkStatus();
  return InvalidField("map_id", absl::StrCat("'", Preview(map_id),
                                              "' must be 1-64 characters of [A-Za-z0-9_-]"));
}

absl::StatusOr<MapStore> MapStore::Open(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) return absl::InternalError(absl::StrCat("cannot create map directory ", directory, ": ", error.message()));
  return MapStore(directory);
}

std::string MapStore::PathOf(const std::string& map_id) const { return absl::StrCat(directory_, "/", map_id, kSuffix); }

absl::StatusOr<StoredMap> MapStore::Save(const std::string& map_id, const std::string& payload) const {
  if (absl::Status s = ValidateMapId(map_id); !s.ok()) return s;
  std::string file(kMagic, kMagicSize);
  PutLe(file, payload.size(), 8);
  PutLe(file, Crc32(payload), 4);
  file += payload;
  const std::string path = PathOf(map_id);
  const std::string temp = path + ".tmp";
  if (absl::Status s = WriteDurably(temp, file); !s.ok()) return s;
  if (std::rename(temp.c_str(), path.c_str()) != 0) return ErrnoStatus("rename", temp);
  if (absl::Status s = SyncDirectory(directory_); !s.ok()) return s;
  return Stat(map_id);
}

absl::StatusOr<std::string> MapStore::Load(const std::string& map_id) const {
  if (absl::Status s = ValidateMapId(map_id); !s.ok()) return s;
  std::ifstream in(PathOf(map_id), std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat("map_id: no stored map '", map_id, "'"));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string file = buffer.str();
  if (file.size() < kHeaderSize || file.compare(0, kMagicSize, kMagic) != 0) {
    return absl::DataLossError(absl::StrCat("map_id: stored map '", map_id, "' has no valid header"));
  }
  const uint64_t size = GetLe(file, kMagicSize, 8);
  const auto crc = static_cast<uint32_t>(GetLe(file, kMagicSize + 8, 4));
  if (file.size() - kHeaderSize != size) {
    return absl::DataLossError(absl::StrCat("map_id: stored map '", map_id, "' is truncated (", file.size() - kHeaderSize,
                                            " of ", size, " payload bytes)"));
  }
  std::string payload = file.substr(kHeaderSize);
  if (Crc32(payload) != crc) {
    return absl::DataLossError(absl::StrCat("map_id: stored map '", map_id, "' fails its checksum"));
  }
  return payload;
}

absl::StatusOr<StoredMap> MapStore::Stat(const std::string& map_id) const {
  std::error_code error;
  const std::string path = PathOf(map_id);
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return absl::NotFoundError(absl::StrCat("map_id: no stored map '", map_id, "'"));
  const auto written = std::filesystem::last_write_time(path, error);
  const auto system_time = std::chrono::file_clock::to_sys(written);
  return StoredMap{map_id, size,
                   std::chrono::duration_cast<std::chrono::nanoseconds>(system_time.time_since_epoch()).count()};
}

absl::StatusOr<std::vector<StoredMap>> MapStore::List() const {
  std::vector<StoredMap> maps;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory_, error)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != kSuffix) continue;
    const std::string id = name.substr(0, name.size() - std::strlen(kSuffix));
    absl::StatusOr<StoredMap> info = Stat(id);
    if (info.ok()) maps.push_back(*info);
  }
  if (error) return absl::InternalError(absl::StrCat("cannot list ", directory_, ": ", error.message()));
  std::sort(maps.begin(), maps.end(), [](const StoredMap& a, const StoredMap& b) { return a.map_id < b.map_id; });
  return maps;
}

absl::Status MapStore::Delete(const std::string& map_id) const {
  if (absl::Status s = ValidateMapId(map_id); !s.ok()) return s;
  std::error_code error;
  if (!std::filesystem::remove(PathOf(map_id), error)) {
    if (error) return absl::InternalError(absl::StrCat("cannot delete ", map_id, ": ", error.message()));
    return absl::NotFoundError(absl::StrCat("map_id: no stored map '", map_id, "'"));
  }
  return SyncDirectory(directory_);
}

}  // namespace semnav::mapping
