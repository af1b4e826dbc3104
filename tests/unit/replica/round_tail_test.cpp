// The round message's tail (replica/round_tail.h): named fields, one order.
#include "replica/round_tail.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace relt {
namespace {

TEST(RoundTail, ReadsBackWhatWasAppendedAfterTheTargets) {
  const std::vector<double> sums = {1.5, 2.5, 3.5};
  RoundTail tail;
  tail.largeSums = sums;
  tail.largeCount = 7.0;
  tail.seconds = 0.25;
  tail.save = true;
  tail.elapsed = 12.0;
  std::vector<double> message = {9.0, 8.0, 7.0, 6.0, 5.0, 4.0};  // the chains' targets come first
  appendRoundTail(tail, message);
  ASSERT_EQ(message.size(), 6 + roundTailLength(3, true));
  const RoundTail back = readRoundTail(message, 3, true);
  ASSERT_EQ(back.largeSums.size(), 3u);
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(back.largeSums[k], sums[k]);
  EXPECT_EQ(back.largeCount, 7.0);
  EXPECT_EQ(back.seconds, 0.25);
  EXPECT_FALSE(back.stop);
  EXPECT_TRUE(back.save);
  EXPECT_EQ(back.elapsed, 12.0);
}

TEST(RoundTail, EveryRequestCombinationTravels) {
  for (int bits = 0; bits < 4; ++bits) {
    RoundTail tail;
    tail.stop = (bits & 1) != 0;
    tail.save = (bits & 2) != 0;
    std::vector<double> message;
    appendRoundTail(tail, message);
    const RoundTail back = readRoundTail(message, 4, false);
    EXPECT_EQ(back.stop, tail.stop) << bits;
    EXPECT_EQ(back.save, tail.save) << bits;
  }
}

TEST(RoundTail, AnInactivePoolSendsNoSums) {
  EXPECT_EQ(roundTailLength(4, false), 4u);
  RoundTail tail;
  tail.largeCount = 3.0;
  std::vector<double> message;
  appendRoundTail(tail, message);
  EXPECT_EQ(message.size(), 4u);
  EXPECT_TRUE(readRoundTail(message, 4, false).largeSums.empty());
  EXPECT_EQ(readRoundTail(message, 4, false).largeCount, 3.0);
}

TEST(RoundTail, AShortMessageIsABrokenInvariant) {
  const std::vector<double> message = {1.0, 2.0, 3.0, 4.0};
  EXPECT_THROW(readRoundTail(message, 2, true), std::logic_error);
}

}  // namespace
}  // namespace relt
