#include "services/relocalization/core/indexed_landmarks.h"

#include <gtest/gtest.h>

namespace semnav::relocalization {
namespace {

Landmark At(double x, Descriptor descriptor) {
  Landmark l;
  l.position = {x, 0.0, 1.0};
  l.scale = 0.5;
  l.descriptor = std::move(descriptor);
  return l;
}

TEST(RelocIndexedLandmarksTest, LookalikeTwinNeedsSameLabelNearIdenticalDescriptorAndDistance) {
  // 0 and 1: boxes of one kind 0.6 m apart, cosine (1 + 0.1*0.12) / sqrt(1.01 * 1.0144) = 0.9998.
  // 2: label 0 too, 0.6 m beyond 1, cosine to 1 = 1 / sqrt(1.0144 * 1.25) = 0.888; to 0 it
  //    is 1.2 m.
  // 3: a different label (arg-max 2) 0.5 m beyond 2, cosine to 2 = 1.0 / sqrt(1.25 * 1.25) = 0.8
  //    would not count even if it were more similar.
  // 4: the same descriptor as 0, but 5 m from everything.
  const IndexedLandmarks landmarks({At(0.0, {1.0f, 0.1f, 0.0f}), At(0.6, {1.0f, 0.12f, 0.0f}),
                                    At(1.2, {1.0f, 0.0f, 0.5f}), At(1.7, {0.5f, 0.0f, 1.0f}),
                                    At(6.7, {1.0f, 0.1f, 0.0f})});
  EXPECT_TRUE(landmarks.HasLookalikeWithin(0, 1.0, 0.95));   // 1 is 0.6 m away, cosine 0.9998
  EXPECT_TRUE(landmarks.HasLookalikeWithin(1, 1.0, 0.95));   // 0
  EXPECT_FALSE(landmarks.HasLookalikeWithin(2, 1.0, 0.95));  // 1 only reaches 0.888
  EXPECT_TRUE(landmarks.HasLookalikeWithin(2, 1.0, 0.88));
  EXPECT_FALSE(landmarks.HasLookalikeWithin(3, 1.0, 0.5));   // 2 is near, but another label
  EXPECT_FALSE(landmarks.HasLookalikeWithin(4, 1.0, 0.95));  // its twin 0 is 6.7 m away
  EXPECT_FALSE(landmarks.HasLookalikeWithin(0, 0.5, 0.95));  // radius below the 0.6 m pitch
}

}  // namespace
}  // namespace semnav::relocalization
