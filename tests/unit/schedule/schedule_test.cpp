#include <gtest/gtest.h>

#include "render/renderer.h"
#include "schedule/schedule.h"

using namespace relt;

TEST(Schedule, EveryUnitHasExactlyOneOwnerForAnyRankCount) {
  for (int ranks = 1; ranks <= 7; ++ranks)
    for (uint64_t k = 0; k < 5; ++k)
      for (int row = 0; row < 13; ++row) {
        int owners = 0;
        for (int r = 0; r < ranks; ++r) owners += ownsUnit(k, row, 13, r, ranks);
        EXPECT_EQ(owners, 1);
      }
}

TEST(Schedule, WorkIsBalancedAcrossRanks) {
  const int height = 100, ranks = 3;
  int counts[ranks] = {};
  for (uint64_t k = 0; k < 9; ++k)
    for (int row = 0; row < height; ++row)
      for (int r = 0; r < ranks; ++r) counts[r] += ownsUnit(k, row, height, r, ranks);
  for (int r = 0; r < ranks; ++r) EXPECT_EQ(counts[r], 300);
}

TEST(Schedule, TimedRenderStopsBeforeOverrunningTheBudget) {
  EXPECT_TRUE(startAnotherPass(0, 0.0, 0.0, 1.0));
  EXPECT_TRUE(startAnotherPass(0, 5.0, 5.0, 1.0));  // the first pass always runs
  EXPECT_TRUE(startAnotherPass(3, 0.6, 0.2, 1.0));
  EXPECT_FALSE(startAnotherPass(4, 0.9, 0.2, 1.0));
}

TEST(Schedule, PassChunksAimAtATenthOfASecondGrowAtMostFourfoldAndStayWithinAPass) {
  EXPECT_EQ(nextPassChunk(4, 0.001, 1000), 16);  // far too short: four times the last
  EXPECT_EQ(nextPassChunk(64, 0.2, 1000), 32);   // too long: the rows of a tenth of a second
  EXPECT_EQ(nextPassChunk(10, 0.1, 1000), 10);
  EXPECT_EQ(nextPassChunk(400, 0.01, 768), 768);  // at most a pass
  EXPECT_EQ(nextPassChunk(3, 30.0, 1000), 1);     // at least a row
  EXPECT_EQ(nextPassChunk(5, 0.0, 1000), 20);     // untimed (a stall-free clock tick): grow
}

TEST(Schedule, APassStoppedInsideIsResolvedRowByRowByEachPixelsOwnSamples) {
  Film film(2, 3);
  std::vector<double> sums(film.data().size(), 6.0);
  const Image image = Renderer::resolve(film, sums, 2, 1);  // 2 passes and row 0 of the third
  for (size_t i = 0; i < image.rgb.size(); ++i) EXPECT_FLOAT_EQ(image.rgb[i], i < 6 ? 2.0f : 3.0f) << i;
  EXPECT_EQ(Renderer::resolve(film, sums, 1, 0).rgb, Renderer::resolve(film, sums, 1.0).rgb);
}

TEST(ProgressLine, ShowsPercentElapsedEtaAndRateInTheGivenUnit) {
  EXPECT_EQ(progressLine(0.5, 2.0, 1.5e6), " 50.0%  2.0 s elapsed  ETA 2.0 s  1.50 M samples/s");
  EXPECT_EQ(progressLine(0.25, 1.0, 2e5, "mutations"), " 25.0%  1.0 s elapsed  ETA 3.0 s  0.20 M mutations/s");
  EXPECT_EQ(progressLine(0.0, 0.0, 0.0), "  0.0%  0.0 s elapsed  ETA 0.0 s  0.00 M samples/s");
}
