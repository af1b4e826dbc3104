// What a pass loop's image shows inside a pass, and what its checkpoint keeps.
#include <gtest/gtest.h>

#include "render/pass_film.h"

using namespace relt;

namespace {

void splat(PassFilm& film, double value) {
  film.live().addSplat(Vec2(0.5, 0.5), Color(value), 1.0);
  if (!film.tally().empty()) film.tally()[0] += 1.0;
}

}  // namespace

TEST(PassFilm, RowsThatStandAloneShowTheLiveSumsEverywhere) {
  PassFilm film(2, 2, true);
  splat(film, 1.0);
  film.passEnded();
  splat(film, 2.0);
  const PassPoint inside{1, 1};
  EXPECT_EQ(film.shown(inside).passes, 1);
  EXPECT_EQ(film.shown(inside).rows, 1);
  EXPECT_DOUBLE_EQ(film.sumsShown(inside)[0], 3.0);
  EXPECT_EQ(film.checkpointFilms(inside).size(), 1u);
}

TEST(PassFilm, InsideAPassOtherwiseTheLastPassEndIsShownAndKept) {
  PassFilm film(2, 2, false, 4);
  splat(film, 1.0);
  film.passEnded();
  splat(film, 2.0);  // a light path of pass 1 splats into pixel 0 from a row not yet done
  const PassPoint inside{1, 1}, between{2, 0};
  EXPECT_EQ(film.shown(inside).passes, 1);
  EXPECT_EQ(film.shown(inside).rows, 0);
  EXPECT_DOUBLE_EQ(film.sumsShown(inside)[0], 1.0);
  EXPECT_DOUBLE_EQ(film.tallyShown(inside)[0], 1.0);
  ASSERT_EQ(film.checkpointFilms(inside).size(), 2u);
  EXPECT_DOUBLE_EQ(film.checkpointFilms(inside)[0].data()[0], 3.0);
  EXPECT_DOUBLE_EQ(film.checkpointFilms(inside)[1].data()[0], 1.0);
  EXPECT_EQ(film.checkpointTallies(inside).size(), 2u);
  film.passEnded();
  EXPECT_DOUBLE_EQ(film.sumsShown(between)[0], 3.0);
  EXPECT_EQ(film.checkpointFilms(between).size(), 1u);
}

TEST(PassFilm, ARestoreBetweenPassesTakesTheLiveSumsAsTheWholePasses) {
  PassFilm film(2, 2, false);
  film.checkpointFilms({3, 0})[0].data()[0] = 5.0;  // as restoreFilms does
  film.restored({3, 0});
  film.live().data()[0] += 1.0;  // the next pass begins
  EXPECT_DOUBLE_EQ(film.sumsShown({3, 1})[0], 5.0);
}

TEST(PassFilm, ARestoreInsideAPassKeepsBothFilms) {
  PassFilm film(2, 2, false);
  const PassPoint inside{3, 1};
  film.checkpointFilms(inside)[0].data()[0] = 7.0;
  film.checkpointFilms(inside)[1].data()[0] = 5.0;
  film.restored(inside);
  EXPECT_DOUBLE_EQ(film.sumsShown(inside)[0], 5.0);
  film.passEnded();
  EXPECT_DOUBLE_EQ(film.sumsShown({4, 1})[0], 7.0);
}

TEST(PassFilm, ASnapshotIsNewOnlyWhenTheImageWouldChange) {
  PassFilm rows(2, 4, true), whole(2, 4, false);
  EXPECT_FALSE(whole.showsNew({0, 3}, std::nullopt));  // black: nothing to show yet
  EXPECT_TRUE(rows.showsNew({0, 3}, std::nullopt));
  EXPECT_FALSE(whole.showsNew({1, 2}, PassPoint{1, 1}));  // the same whole pass
  EXPECT_TRUE(rows.showsNew({1, 2}, PassPoint{1, 1}));
  EXPECT_TRUE(whole.showsNew({2, 0}, PassPoint{1, 3}));
  EXPECT_FALSE(rows.showsNew({1, 1}, PassPoint{1, 1}));
}

// Each worker thread adds to sums of its own; gathered, they are the live sums (and tallies), and
// a pass end gathers them before its copy.
TEST(PassFilm, WorkersSumsAreGatheredIntoTheLiveOnes) {
  PassFilm film(2, 2, false, 4, 3);
  EXPECT_EQ(&film.workerFilm(0), &film.live());
  for (int w = 0; w < 3; ++w) {
    film.workerFilm(w).addSplat(Vec2(0.5, 1.5), Color(double(w + 1)), 1.0);
    (*film.workerTally(w))[2] += 1.0;
  }
  film.passEnded();
  EXPECT_DOUBLE_EQ(film.live().data()[6], 6.0);
  EXPECT_DOUBLE_EQ(film.tally()[2], 3.0);
  EXPECT_DOUBLE_EQ(film.sumsShown({1, 0})[6], 6.0) << "the copy at the pass end has every worker's";
  film.workerFilm(2).addSplat(Vec2(1.5, 0.5), Color(5.0), 1.0);
  EXPECT_DOUBLE_EQ(film.live().data()[3], 0.0) << "not gathered yet";
  film.gatherWorkers();
  EXPECT_DOUBLE_EQ(film.live().data()[3], 5.0);
  EXPECT_DOUBLE_EQ(film.workerFilm(2).data()[3], 0.0) << "a worker's sums start again from zero";
  film.gatherWorkers();
  EXPECT_DOUBLE_EQ(film.live().data()[3], 5.0) << "gathered once";
  EXPECT_EQ(PassFilm(2, 2, true).workerTally(0), nullptr) << "no tally kept";
}
