// The expected duration of a timed render's next pass or round.
#include <gtest/gtest.h>

#include "schedule/pace.h"

using namespace relt;

TEST(Pace, OneStalledPassDoesNotChangeTheGuess) {
  Pace pace;
  EXPECT_EQ(pace.typical(), 0.0);
  for (int i = 0; i < 10; ++i) pace.add(0.1);
  pace.add(3.0);  // a rank was paused
  EXPECT_DOUBLE_EQ(pace.typical(), 0.1);
}

TEST(Pace, FollowsALastingChangeOfSpeedWithinHalfAWindow) {
  Pace pace;
  for (size_t i = 0; i < Pace::kWindow; ++i) pace.add(0.1);
  for (size_t i = 0; i < Pace::kWindow / 2; ++i) pace.add(0.3);
  EXPECT_DOUBLE_EQ(pace.typical(), 0.1);
  pace.add(0.3);
  EXPECT_DOUBLE_EQ(pace.typical(), 0.3);
}

TEST(Pace, RoundsReadBackTogetherCountOnceEach) {
  Pace pace;
  pace.add(3.2, 32);  // 32 rounds in 3.2 s
  pace.add(0.5);
  EXPECT_DOUBLE_EQ(pace.typical(), 0.1);
  pace.add(-1.0);  // a clock that went back (no time), and nothing: ignored
  pace.add(1.0, 0);
  EXPECT_DOUBLE_EQ(pace.typical(), 0.1);
}
