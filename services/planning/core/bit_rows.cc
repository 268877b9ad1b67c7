#include "services/planning/core/bit_rows.h"

#include <algorithm>

namespace semnav::planning {
namespace {

// In-place transpose of a 64 x 64 bit block, a[k] bit i = element (k, i):
// swaps the off-diagonal halves, then quarters, ... (Hacker's Delight 7-3).
void Transpose64(uint64_t a[64]) {
  uint64_t mask = 0x00000000FFFFFFFFull;
  for (int j = 32; j != 0; j >>= 1, mask ^= mask << j) {
    for (int k = 0; k < 64; k = ((k | j) + 1) & ~j) {
      const uint64_t t = ((a[k] >> j) ^ a[k | j]) & mask;
      a[k] ^= t << j;
      a[k | j] ^= t;
    }
  }
}

}  // namespace

BitRows BitRows::Transposed() const {
  BitRows out(columns_, rows_);
  uint64_t block[64];
  for (int r0 = 0; r0 < rows_; r0 += 64) {
    const int block_rows = std::min(64, rows_ - r0);
    for (int w = 0; w < words_per_row_; ++w) {
      for (int k = 0; k < 64; ++k) block[k] = k < block_rows ? row(r0 + k)[w] : 0;
      Transpose64(block);
      const int block_columns = std::min(64, columns_ - w * 64);
      for (int k = 0; k < block_columns; ++k) out.row(w * 64 + k)[r0 >> 6] = block[k];
    }
  }
  return out;
}

}  // namespace semnav::planning
