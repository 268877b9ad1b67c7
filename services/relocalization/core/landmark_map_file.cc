#include "services/relocalization/core/landmark_map_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "absl/strings/str_cat.h"
#include "absl/strings/string_view.h"

namespace semnav::relocalization {
namespace {

constexpr char kMagic[8] = {'S', 'N', 'L', 'M', 'A', 'P', '0', '1'};

uint64_t Fnv1a64(const std::string& bytes) {
  uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

template <typename T>
void Put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

// Reads fixed-size values from the payload; false once the bytes run out.
class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  bool Get(T* value) {
    if (bytes_.size() - pos_ < sizeof(T)) return false;
    std::memcpy(value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return true;
  }
  size_t remaining() const { return bytes_.size() - pos_; }

 private:
  const std::string& bytes_;
  size_t pos_ = 0;
};

std::string Encode(const LandmarkMap& map) {
  std::string out(kMagic, sizeof(kMagic));
  Put(out, map.revision());
  Put(out, map.next_id());
  Put(out, static_cast<uint64_t>(map.descriptor_dim()));
  Put(out, static_cast<uint64_t>(map.landmarks().size()));
  for (const Landmark& l : map.landmarks()) {
    Put(out, l.id);
    for (int a = 0; a < 3; ++a) Put(out, l.position[a]);
    Put(out, l.scale);
    Put(out, l.observations);
    out.append(reinterpret_cast<const char*>(l.descriptor.data()), l.descriptor.size() * sizeof(float));
  }
  Put(out, Fnv1a64(out));
  return out;
}

absl::Status ErrnoError(absl::string_view what, const std::string& path) {
  return absl::InternalError(absl::StrCat(what, " ", path, ": ", std::strerror(errno)));
}

absl::Status SyncPath(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) return ErrnoError("open", path);
  const int rc = ::fsync(fd);
  ::close(fd);
  return rc == 0 ? absl::OkStatus() : ErrnoError("fsync", path);
}

}  // namespace

absl::Status WriteLandmarkMapFile(const std::string& path, const LandmarkMap& map) {
  const std::string bytes = Encode(map);
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return ErrnoError("open", tmp);
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const absl::Status s = ErrnoError("write", tmp);
      ::close(fd);
      ::unlink(tmp.c_str());
      return s;
    }
    written += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const absl::Status s = ErrnoError("fsync", tmp);
    ::close(fd);
    ::unlink(tmp.c_str());
    return s;
  }
  ::close(fd);
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const absl::Status s = ErrnoError("rename", tmp);
    ::unlink(tmp.c_str());
    return s;
  }
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return SyncPath(parent.empty() ? "." : parent.string(), O_RDONLY | O_DIRECTORY);
}

absl::StatusOr<LandmarkMap> ReadLandmarkMapFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat("no landmark map file ", path));
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto corrupt = [&](absl::string_view why) {
    return absl::DataLossError(absl::StrCat("landmark map file ", path, " is corrupt: ", why));
  };
  if (bytes.size() < sizeof(kMagic) + sizeof(uint64_t) ||
      std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) {
    return corrupt("bad header");
  }
  const std::string payload = bytes.substr(0, bytes.size() - sizeof(uint64_t));
  uint64_t stored_sum = 0;
  std::memcpy(&stored_sum, bytes.data() + payload.size(), sizeof(stored_sum));
  if (stored_sum != Fnv1a64(payload)) return corrupt("checksum mismatch");

  Reader r(payload);
  char magic[sizeof(kMagic)];
  uint64_t revision = 0, next_id = 0, dim = 0, count = 0;
  if (!r.Get(&magic) || !r.Get(&revision) || !r.Get(&next_id) || !r.Get(&dim) || !r.Get(&count)) {
    return corrupt("truncated header");
  }
  const uint64_t per_landmark = 8 + 3 * 8 + 8 + 4 + dim * 4;
  if (dim == 0 && count > 0) return corrupt("zero descriptor length");
  if (count > r.remaining() / per_landmark || r.remaining() != count * per_landmark) {
    return corrupt("size does not match the landmark count");
  }
  std::vector<Landmark> landmarks(count);
  for (Landmark& l : landmarks) {
    r.Get(&l.id);
    for (int a = 0; a < 3; ++a) r.Get(&l.position[a]);
    r.Get(&l.scale);
    r.Get(&l.observations);
    l.descriptor.resize(dim);
    for (float& v : l.descriptor) r.Get(&v);
  }
  return LandmarkMap(std::move(landmarks), next_id, revision);
}

}  // namespace semnav::relocalization
