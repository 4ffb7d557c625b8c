#include "core/sensors/timestamp_pairer.h"

#include <gtest/gtest.h>

#include <string>

namespace sightline {
namespace {

TEST(TimestampPairer, PairsItemsWithinTolerance) {
  TimestampPairer<std::string> pairer(0.005);
  EXPECT_FALSE(pairer.Add(0, 1.000, "L1"));
  auto pair = pairer.Add(1, 1.003, "R1");
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->first, "L1");
  EXPECT_EQ(pair->second, "R1");
  EXPECT_EQ(pairer.pending(), 0u);
  EXPECT_EQ(pairer.paired(), 1u);
  EXPECT_EQ(pairer.unpaired(), 0u);
}

TEST(TimestampPairer, DropsItemsThatCanNoLongerPairAndCountsThem) {
  TimestampPairer<int> pairer(0.005);
  EXPECT_FALSE(pairer.Add(0, 1.00, 1));
  EXPECT_FALSE(pairer.Add(0, 1.04, 2));
  // The right stream starts at 1.04: left 1.00 is too old for it and any later right frame.
  auto pair = pairer.Add(1, 1.041, 20);
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->first, 2);
  EXPECT_EQ(pair->second, 20);
  EXPECT_EQ(pairer.unpaired(), 1u);
}

TEST(TimestampPairer, PrefersTheCloserOfTwoWaitingItems) {
  TimestampPairer<int> pairer(0.010);
  EXPECT_FALSE(pairer.Add(0, 1.000, 1));
  EXPECT_FALSE(pairer.Add(0, 1.008, 2));
  auto pair = pairer.Add(1, 1.009, 9);  // Within tolerance of both; 1.008 is closer.
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->first, 2);
  EXPECT_EQ(pairer.unpaired(), 1u);
}

TEST(TimestampPairer, BoundsWaitingItemsPerStream) {
  TimestampPairer<int> pairer(0.001, 3);
  for (int i = 0; i < 10; ++i) EXPECT_FALSE(pairer.Add(0, i * 0.1, i));
  EXPECT_EQ(pairer.pending(), 3u);
  EXPECT_EQ(pairer.unpaired(), 7u);
  auto pair = pairer.Add(1, 0.9, 90);
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->first, 9);
  EXPECT_EQ(pairer.unpaired(), 9u);  // 0.7 and 0.8 were passed by the right stream.
}

TEST(TimestampPairer, ClearForgetsWithoutCounting) {
  TimestampPairer<int> pairer(0.001);
  pairer.Add(0, 1.0, 1);
  pairer.Clear();
  EXPECT_EQ(pairer.pending(), 0u);
  EXPECT_EQ(pairer.unpaired(), 0u);
  EXPECT_FALSE(pairer.Add(1, 1.0, 2));
}

}  // namespace
}  // namespace sightline
