#include "services/planning/core/bit_rows.h"

#include <gtest/gtest.h>

#include <random>

namespace semnav::planning {
namespace {

TEST(BitRows, NextAndPreviousSetBitAcrossWords) {
  BitRows bits(2, 130);  // 3 words per row, the last one 2 columns wide
  bits.Set(0, 3);
  bits.Set(0, 64);
  bits.Set(0, 129);
  EXPECT_EQ(bits.NextSetAfter(0, -1), 3);
  EXPECT_EQ(bits.NextSetAfter(0, 3), 64);
  EXPECT_EQ(bits.NextSetAfter(0, 64), 129);
  EXPECT_EQ(bits.NextSetAfter(0, 129), 192);  // none: the padded row length
  EXPECT_EQ(bits.PreviousSetBefore(0, 130), 129);
  EXPECT_EQ(bits.PreviousSetBefore(0, 129), 64);
  EXPECT_EQ(bits.PreviousSetBefore(0, 64), 3);
  EXPECT_EQ(bits.PreviousSetBefore(0, 3), -1);
  EXPECT_EQ(bits.NextSetAfter(1, 0), 192);  // other rows untouched
  EXPECT_TRUE(bits.Get(0, 64));
  EXPECT_FALSE(bits.Get(1, 64));
}

TEST(BitRows, NeighbourColumnWordsCarryAcrossWords) {
  BitRows bits(1, 100);
  bits.Set(0, 63);
  bits.Set(0, 64);
  // Bit c of PreviousColumnWord is bit c - 1: 63 -> 64, 64 -> 65.
  EXPECT_EQ(bits.PreviousColumnWord(0, 0), 0u);
  EXPECT_EQ(bits.PreviousColumnWord(0, 1), 0b11u);
  // Bit c of NextColumnWord is bit c + 1: 63 -> 62, 64 -> 63.
  EXPECT_EQ(bits.NextColumnWord(0, 0), uint64_t{0b11} << 62);
  EXPECT_EQ(bits.NextColumnWord(0, 1), 0u);
}

TEST(BitRows, TransposedSwapsRowsAndColumns) {
  std::mt19937 rng(5);
  BitRows bits(70, 131);  // partial 64 x 64 blocks both ways
  for (int k = 0; k < 2000; ++k) bits.Set(rng() % 70, rng() % 131);
  const BitRows t = bits.Transposed();
  ASSERT_EQ(t.rows(), 131);
  ASSERT_EQ(t.columns(), 70);
  for (int r = 0; r < 70; ++r) {
    for (int c = 0; c < 131; ++c) ASSERT_EQ(t.Get(c, r), bits.Get(r, c)) << r << "," << c;
  }
  // Padding stays clear: nothing past the last column of any row.
  for (int r = 0; r < t.rows(); ++r) EXPECT_EQ(t.NextSetAfter(r, 69), 128);
}

}  // namespace
}  // namespace semnav::planning
