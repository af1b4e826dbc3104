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

TEST(PassFilm, OnlyPathTracingsRowsStandAlone) {
  EXPECT_TRUE(samplesStayInTheirRow(Integrator::PathTracing));
  for (Integrator i : {Integrator::Bdpt, Integrator::Erpt}) EXPECT_FALSE(samplesStayInTheirRow(i));
}

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
