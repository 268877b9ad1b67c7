#include "services/relocalization/core/landmark_map_file.h"

#include <cstring>

#include "absl/strings/str_cat.h"
#include "absl/strings/string_view.h"
#include "services/common/storage/durable_file.h"

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
    out.append(reinterpret_cast<const char*>(l.descriptor.data()),
               l.descriptor.size() * sizeof(float));
  }
  Put(out, Fnv1a64(out));
  return out;
}

}  // namespace

absl::Status WriteLandmarkMapFile(const std::string& path, const LandmarkMap& map) {
  return storage::WriteFileAtomically(path, Encode(map));
}

absl::StatusOr<LandmarkMap> ReadLandmarkMapFile(const std::string& path) {
  absl::StatusOr<std::string> file = storage::ReadWholeFile(path);
  if (absl::IsNotFound(file.status()))
    return absl::NotFoundError(absl::StrCat("no landmark map file ", path));
  if (!file.ok()) return file.status();
  const std::string& bytes = *file;
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
  // Bounded before it is multiplied (found by fuzz_landmark_map_file: a huge dim wrapped the
  // per-landmark size and passed the size check).
  if (dim > kMaxDescriptorDim) return corrupt("descriptor length beyond the limit");
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
