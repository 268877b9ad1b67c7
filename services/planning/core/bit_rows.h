#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace semnav::planning {

// A bit matrix stored as rows of 64-bit words (bit i of word w is column
// 64 w + i). Columns past `columns` are padding and read as 0 unless set.
// Lets whole-grid tests run 64 cells per operation and finds the next set
// bit along a row with one count-zeros per word.
class BitRows {
 public:
  BitRows() = default;
  BitRows(int rows, int columns)
      : rows_(rows),
        columns_(columns),
        words_per_row_((columns + 63) / 64),
        words_(static_cast<std::size_t>(rows) * words_per_row_, 0) {}

  int rows() const { return rows_; }
  int columns() const { return columns_; }
  int words_per_row() const { return words_per_row_; }
  uint64_t* row(int r) { return words_.data() + static_cast<std::size_t>(r) * words_per_row_; }
  const uint64_t* row(int r) const {
    return words_.data() + static_cast<std::size_t>(r) * words_per_row_;
  }

  bool Get(int r, int c) const { return (row(r)[c >> 6] >> (c & 63) & 1) != 0; }
  void Set(int r, int c) { row(r)[c >> 6] |= uint64_t{1} << (c & 63); }

  // The first set column > c in row r, or columns_padded() when none.
  int NextSetAfter(int r, int c) const {
    const uint64_t* w = row(r);
    int i = (c + 1) >> 6;
    if (i >= words_per_row_) return words_per_row_ * 64;
    uint64_t word = w[i] & (~uint64_t{0} << ((c + 1) & 63));
    while (word == 0) {
      if (++i == words_per_row_) return words_per_row_ * 64;
      word = w[i];
    }
    return i * 64 + __builtin_ctzll(word);
  }
  // The last set column < c in row r, or -1 when none.
  int PreviousSetBefore(int r, int c) const {
    if (c <= 0) return -1;
    const uint64_t* w = row(r);
    int i = (c - 1) >> 6;
    uint64_t word = w[i] & (~uint64_t{0} >> (63 - ((c - 1) & 63)));
    while (word == 0) {
      if (--i < 0) return -1;
      word = w[i];
    }
    return i * 64 + 63 - __builtin_clzll(word);
  }

  // Word w of the row whose bit c is bit c - 1 of row r (0 at column 0).
  uint64_t PreviousColumnWord(int r, int w) const {
    const uint64_t* v = row(r);
    return v[w] << 1 | (w > 0 ? v[w - 1] >> 63 : 0);
  }
  // Word w of the row whose bit c is bit c + 1 of row r (0 past the end).
  uint64_t NextColumnWord(int r, int w) const {
    const uint64_t* v = row(r);
    return v[w] >> 1 | (w + 1 < words_per_row_ ? v[w + 1] << 63 : 0);
  }

  // The matrix with rows and columns swapped (64 x 64 blocks at a time).
  BitRows Transposed() const;

 private:
  int rows_ = 0;
  int columns_ = 0;
  int words_per_row_ = 0;
  std::vector<uint64_t> words_;
};

}  // namespace semnav::planning
