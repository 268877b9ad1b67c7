#include "services/planning/core/region_tables.h"

#include <bit>
#include <cstring>

namespace semnav::planning {
namespace {

constexpr uint64_t kLowBits = 0x7F7F7F7F7F7F7F7Full;
constexpr uint64_t kHighBits = 0x8080808080808080ull;

static_assert(std::endian::native == std::endian::little, "byte i of a word is cell i");

// One bit per byte of `bytes` (bit i = byte i) from per-byte flags in the
// bytes' high bits: the multiply gathers the 8 flags into the top byte.
uint64_t GatherHighBits(uint64_t flags) {
  return ((flags & kHighBits) >> 7) * 0x0102040810204080ull >> 56;
}

// Classes of 8 cells at once (SWAR): bit i of *free / *obstacle is cell i.
// Byte tests without carries between bytes: (b & 0x7F) + k sets the high
// bit exactly when (b & 0x7F) >= 128 - k.
void ClassifyEight(const uint8_t* cells, uint64_t* free, uint64_t* obstacle) {
  uint64_t bytes;
  std::memcpy(&bytes, cells, sizeof bytes);
  const uint64_t low = bytes & kLowBits;
  const uint64_t nonzero = (low + kLowBits) | bytes;
  const uint64_t at_least_structure =
      (low + (128 - kStructureValue) * 0x0101010101010101ull) | bytes;
  *free = GatherHighBits(~nonzero);
  *obstacle = GatherHighBits(nonzero & ~at_least_structure);
}

// Row r of `bits` widened by one column each way (0 outside the grid).
void WidenRow(const BitRows& bits, int r, uint64_t* out) {
  for (int w = 0; w < bits.words_per_row(); ++w) {
    out[w] = bits.row(r)[w] | bits.PreviousColumnWord(r, w) | bits.NextColumnWord(r, w);
  }
}

// Each cell's 3 x 3 neighbourhood OR-ed together (cells outside are 0).
BitRows Dilated(const BitRows& bits) {
  BitRows wide(bits.rows(), bits.columns());
  for (int r = 0; r < bits.rows(); ++r) WidenRow(bits, r, wide.row(r));
  BitRows out(bits.rows(), bits.columns());
  for (int r = 0; r < bits.rows(); ++r) {
    for (int w = 0; w < bits.words_per_row(); ++w) {
      uint64_t v = wide.row(r)[w];
      if (r > 0) v |= wide.row(r - 1)[w];
      if (r + 1 < bits.rows()) v |= wide.row(r + 1)[w];
      out.row(r)[w] = v;
    }
  }
  return out;
}

}  // namespace

RegionTables::RegionTables(LayeredGrid grid) : grid_(std::move(grid)) {
  const int width = grid_.width();
  const int height = grid_.height();
  BitRows free(height, width);
  BitRows obstacle(height, width);
  for (int y = 0; y < height; ++y) {
    const uint8_t* v = grid_.values().data() + static_cast<size_t>(y) * width;
    for (int w = 0; w < free.words_per_row(); ++w) {
      const int first = w * 64;
      const int count = width - first < 64 ? width - first : 64;
      uint64_t is_free = 0;
      uint64_t is_obstacle = 0;
      int i = 0;
      for (; i + 8 <= count; i += 8) {
        uint64_t f;
        uint64_t o;
        ClassifyEight(v + first + i, &f, &o);
        is_free |= f << i;
        is_obstacle |= o << i;
      }
      for (; i < count; ++i) {  // the row's last cells when width % 8 != 0
        is_free |= static_cast<uint64_t>(v[first + i] == 0) << i;
        is_obstacle |= static_cast<uint64_t>(IsObstacle(v[first + i])) << i;
      }
      free.row(y)[w] = is_free;
      obstacle.row(y)[w] = is_obstacle;
    }
  }
  // Boundary: a cell of one class with a cell of the other among its 8
  // neighbours (the classes are disjoint, so the cell itself never counts).
  const BitRows near_free = Dilated(free);
  const BitRows near_obstacle = Dilated(obstacle);
  boundary_ = BitRows(height, width);
  BitRows open(height, width);
  for (int y = 0; y < height; ++y) {
    for (int w = 0; w < free.words_per_row(); ++w) {
      boundary_.row(y)[w] =
          (free.row(y)[w] & near_obstacle.row(y)[w]) | (obstacle.row(y)[w] & near_free.row(y)[w]);
      open.row(y)[w] = free.row(y)[w] | obstacle.row(y)[w];
    }
  }
  jumps_.Build(open, boundary_);
}

size_t RegionTables::bytes() const {
  return grid_.values().size() +
         static_cast<size_t>(boundary_.rows()) * boundary_.words_per_row() * sizeof(uint64_t) +
         jumps_.bytes();
}

}  // namespace semnav::planning
