#include "services/common/storage/durable_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "absl/strings/str_cat.h"

namespace semnav::storage {
namespace {

absl::Status ErrnoStatus(absl::string_view what, const std::string& path) {
  return absl::InternalError(absl::StrCat(what, " ", path, ": ", std::strerror(errno)));
}

absl::Status WriteAndSync(int fd, const std::string& path,
                          std::initializer_list<absl::string_view> pieces) {
  for (const absl::string_view bytes : pieces) {
    size_t written = 0;
    while (written < bytes.size()) {
      const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) return ErrnoStatus("write", path);
      written += static_cast<size_t>(n);
    }
  }
  if (::fsync(fd) != 0) return ErrnoStatus("fsync", path);
  return absl::OkStatus();
}

absl::Status SyncDirectory(const std::string& directory) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return ErrnoStatus("open", directory);
  const int rc = ::fsync(fd);
  ::close(fd);
  return rc == 0 ? absl::OkStatus() : ErrnoStatus("fsync", directory);
}

std::array<uint32_t, 256> MakeCrcTable() {
  std::array<uint32_t, 256> table{};
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[i] = c;
  }
  return table;
}

void PutLittleEndian(std::string& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

uint64_t GetLittleEndian(absl::string_view in, size_t offset, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) {
    value |= static_cast<uint64_t>(static_cast<unsigned char>(in[offset + i])) << (8 * i);
  }
  return value;
}

}  // namespace

absl::Status WriteFileAtomically(const std::string& path, absl::string_view bytes) {
  return WriteFileAtomically(path, {bytes});
}

absl::Status WriteFileAtomically(const std::string& path,
                                 std::initializer_list<absl::string_view> pieces) {
  // The pid keeps two processes writing the same file from sharing one temporary.
  const std::string temporary = absl::StrCat(path, ".", ::getpid(), ".tmp");
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return ErrnoStatus("open", temporary);
  absl::Status status = WriteAndSync(fd, temporary, pieces);
  if (::close(fd) != 0 && status.ok()) status = ErrnoStatus("close", temporary);
  if (status.ok() && ::rename(temporary.c_str(), path.c_str()) != 0)
    status = ErrnoStatus("rename", temporary);
  if (!status.ok()) {
    ::unlink(temporary.c_str());
    return status;
  }
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return SyncDirectory(parent.empty() ? "." : parent.string());
}

absl::Status RemoveFileDurably(const std::string& path) {
  if (::unlink(path.c_str()) != 0) {
    if (errno == ENOENT) return absl::NotFoundError(absl::StrCat("no file ", path));
    return ErrnoStatus("unlink", path);
  }
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return SyncDirectory(parent.empty() ? "." : parent.string());
}

absl::StatusOr<std::string> ReadWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat("no file ", path));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return absl::InternalError(absl::StrCat("cannot read ", path));
  return bytes;
}

uint32_t Crc32(absl::string_view data) {
  static const std::array<uint32_t, 256> table = MakeCrcTable();
  uint32_t c = 0xFFFFFFFFu;
  for (unsigned char byte : data) c = table[(c ^ byte) & 0xff] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::string FrameHeader(absl::string_view magic, absl::string_view payload) {
  std::string header(magic.data(), magic.size());
  PutLittleEndian(header, payload.size(), 8);
  PutLittleEndian(header, Crc32(payload), 4);
  return header;
}

std::string FrameWithChecksum(absl::string_view magic, absl::string_view payload) {
  std::string file = FrameHeader(magic, payload);
  file.append(payload.data(), payload.size());
  return file;
}

absl::Status WriteFramedFileAtomically(const std::string& path, absl::string_view magic,
                                       absl::string_view payload) {
  const std::string header = FrameHeader(magic, payload);
  return WriteFileAtomically(path, {header, payload});
}

absl::StatusOr<std::string> PayloadOfFrame(absl::string_view magic, absl::string_view file,
                                           absl::string_view what) {
  const size_t header = magic.size() + 8 + 4;
  if (file.size() < header || file.substr(0, magic.size()) != magic) {
    return absl::DataLossError(absl::StrCat(what, " has no valid header"));
  }
  const uint64_t size = GetLittleEndian(file, magic.size(), 8);
  const auto crc = static_cast<uint32_t>(GetLittleEndian(file, magic.size() + 8, 4));
  if (file.size() - header != size) {
    return absl::DataLossError(absl::StrCat(what, " is truncated (", file.size() - header, " of ",
                                            size, " payload bytes)"));
  }
  const absl::string_view payload = file.substr(header);
  if (Crc32(payload) != crc) return absl::DataLossError(absl::StrCat(what, " fails its checksum"));
  return std::string(payload);
}

}  // namespace semnav::storage
