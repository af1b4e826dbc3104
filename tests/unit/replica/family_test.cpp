// Target families and the MIS over levels: the targets each family defines, which levels estimate
// which class, and that the level weights of every class sum to one.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "replica/family.h"
#include "replica/level_estimator.h"

using namespace relt;

namespace {
FamilySettings kitaokaSettings() {
  FamilySettings s;
  s.kind = FamilyKind::Kitaoka;
  s.kitaokaDelta = 0.5;
  return s;
}
const ClassLuminance kL = {1.0, 2.0, 4.0, 8.0, 16.0, 32.0};
}  // namespace

TEST(ClassLuminance, SumsEachClassAndRefusesANonFinitePath) {
  PathSample p;
  p.add({0, 0}, Color(1.0f), PathClass::L2);
  p.add({0, 0}, Color(2.0f), PathClass::L2);
  p.add({0, 0}, Color(3.0f), PathClass::L5);
  const ClassLuminance L = *classLuminance(p);
  EXPECT_NEAR(L[2], 3.0, 1e-6);
  EXPECT_NEAR(L[5], 3.0, 1e-6);
  EXPECT_EQ(L[0], 0.0);
  p.add({0, 0}, Color(NAN), PathClass::L1);
  EXPECT_FALSE(classLuminance(p).has_value());
}

TEST(LevelFamily, KitaokaLevelsAreSpecificIndirectFullUniform) {
  const LevelFamily f(kitaokaSettings(), 123.0);
  ASSERT_EQ(f.levels(), 4);
  double q[4];
  f.targets(kL, q);
  EXPECT_DOUBLE_EQ(q[0], 1.0 + 0.5 * 32.0);            // L0 + delta L5
  EXPECT_DOUBLE_EQ(q[1], 1.0 + 8.0 + 16.0 + 32.0);     // L0 + L3 + L4 + L5
  EXPECT_DOUBLE_EQ(q[2], 63.0);                         // everything: I (see ARCHITECTURE j)
  EXPECT_DOUBLE_EQ(q[3], 1.0);                          // uniform
  EXPECT_EQ(f.largeStepProbability(3), 1.0f);
  for (int n = 0; n < kPathClassCount; ++n) {
    EXPECT_EQ(f.estimates(0, n), n == 0) << "only the specific level estimates L0";
    for (int k = 1; k < 4; ++k) EXPECT_EQ(f.estimates(k, n), n != 0);
  }
  EXPECT_FLOAT_EQ(f.sizes(1).s2, 16.0f * f.sizes(1).s1);
  EXPECT_LT(f.sizes(0).s1, f.sizes(1).s1);
}

// Bootstrap features: class luminances L0..L5 per sample.
TEST(IdleLevels, AreTheLevelsNoBootstrapSampleReached) {
  const FamilySettings kitaoka = kitaokaSettings();
  const std::vector<double> noImplicitSpecular = {0, 1, 2, 0, 0, 0, 0, 0, 3, 1, 0, 0};
  EXPECT_EQ(idleLevels(kitaoka, noImplicitSpecular), 1u) << "the specific level: target L0 + delta L5 is 0";
  EXPECT_EQ(idleLevels(kitaoka, {0, 1, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0.5}), 1u)
      << "L5 reaches its target, but it estimates L0 alone, and no sample had any";
  EXPECT_EQ(idleLevels(kitaoka, {0.1, 1, 2, 0, 0, 0}), 0u) << "an implicit path after a specular bounce";
  EXPECT_EQ(idleLevels(kitaoka, {0, 0, 2, 0, 0, 0}), 3u) << "indirect (L0 + L3..L5) neither; full and uniform do";
  EXPECT_EQ(idleLevels(kitaoka, std::vector<double>(12, 0.0)), 0u) << "a black bootstrap: nothing to choose";
  FamilySettings relaxed;
  relaxed.kind = FamilyKind::Relaxed;
  EXPECT_EQ(idleLevels(relaxed, noImplicitSpecular), 0u);
  FamilySettings tempered;
  tempered.kind = FamilyKind::Tempered;
  tempered.levels = 2;
  EXPECT_EQ(idleLevels(tempered, {1.0, 0.0, 2.0, 0.0}), 0u) << "tempered levels are never left out";
}

TEST(LevelFamily, ALeftOutLevelHandsItsClassesToTheLevelsThatReachThem) {
  FamilySettings s = kitaokaSettings();
  s.leftOut = 1;  // specific
  const LevelFamily f(s, 1.0);
  ASSERT_EQ(f.levels(), 3);
  EXPECT_EQ(f.name(0), "indirect");
  EXPECT_EQ(f.name(2), "uniform");
  EXPECT_EQ(LevelFamily::leftOutNames(s), std::vector<std::string>{"specific"});
  double q[3];
  f.targets(kL, q);
  EXPECT_DOUBLE_EQ(q[1], 63.0) << "the remaining levels' targets are as before";
  for (int k = 0; k < 3; ++k)
    for (int n = 0; n < kPathClassCount; ++n) EXPECT_TRUE(f.estimates(k, n)) << "level " << k << " class " << n;
  s.leftOut = 2 | 4 | 8;  // all but specific: L1..L4 would have no level whose target reaches them
  EXPECT_THROW(LevelFamily(s, 1.0), std::invalid_argument);
  s.leftOut = 15;
  EXPECT_THROW(LevelFamily(s, 1.0), std::invalid_argument);
}

TEST(LevelFamily, RelaxedEpsGrowGeometricallyWithTheMeanTarget) {
  FamilySettings s;
  s.kind = FamilyKind::Relaxed;
  s.levels = 4;
  s.relaxedEps1 = 0.1;
  s.relaxedRatio = 3.0;
  const LevelFamily f(s, 2.0);
  double q[4];
  f.targets(kL, q);
  const double I = 63.0;
  EXPECT_DOUBLE_EQ(q[0], I);
  EXPECT_DOUBLE_EQ(q[1], I + 0.2);
  EXPECT_DOUBLE_EQ(q[2], I + 0.6);
  EXPECT_NEAR(q[3], I + 1.8, 1e-12);
  for (int k = 0; k < 4; ++k)
    for (int n = 0; n < kPathClassCount; ++n) EXPECT_TRUE(f.estimates(k, n));
}

// For each class, sum over the levels that estimate it of classFactor * (q_k / b_k) = 1: the MIS
// weights w_k = classFactor * density_k form a partition of unity, for balance and power heuristics.
TEST(LevelEstimator, WeightsOfEveryClassSumToOne) {
  for (double beta : {1.0, 2.0}) {
    for (bool kitaoka : {false, true}) {
      FamilySettings s = kitaokaSettings();
      if (!kitaoka) s.kind = FamilyKind::Relaxed;
      if (kitaoka && beta == 2.0) s.leftOut = 1;  // L0 then weighted over the three that remain
      const LevelFamily f(s, 3.0);
      LevelEstimator e(f, beta);
      std::vector<double> b(static_cast<size_t>(f.levels()));
      for (int k = 0; k < f.levels(); ++k) b[size_t(k)] = 0.5 + k;
      e.setNormalisers(b);
      std::vector<double> q(static_cast<size_t>(f.levels()));
      f.targets(kL, q.data());
      for (int n = 0; n < kPathClassCount; ++n) {
        double sum = 0.0;
        for (int k = 0; k < f.levels(); ++k) sum += e.classFactor(q.data(), k, n) * q[size_t(k)] / b[size_t(k)];
        EXPECT_NEAR(sum, 1.0, 1e-12) << "beta " << beta << " kitaoka " << kitaoka << " class " << n;
      }
    }
  }
}

TEST(LevelEstimator, SplatsEachClassWithItsFactor) {
  const LevelFamily f(kitaokaSettings(), 1.0);
  LevelEstimator e(f, 1.0);
  e.setNormalisers({1.0, 1.0, 1.0, 1.0});
  PathSample p;
  p.add({0.5f, 0.5f}, Color(1.0f), PathClass::L0);
  p.add({1.5f, 0.5f}, Color(1.0f), PathClass::L2);
  double q[4];
  f.targets(*classLuminance(p), q);
  Film film(2, 1);
  e.splat(p, q, 0, 1.0, film);  // the specific level: its L0 splat only
  EXPECT_NEAR(film.data()[0], 1.0 / q[0], 1e-6);
  EXPECT_EQ(film.data()[3], 0.0);
  e.splat(p, q, 2, 0.5, film);  // the full level: its L2 splat, weighted over indirect, full, uniform
  EXPECT_NEAR(film.data()[3], 0.5 / (q[1] + q[2] + q[3]), 1e-6);
}

TEST(TemperedFamily, LevelsAreGeometricTemperaturesThatEstimateEveryClass) {
  FamilySettings s;
  s.kind = FamilyKind::Tempered;
  s.levels = 3;
  s.temperatureMax = 100.0;
  const LevelFamily f(s, 1.0);
  ASSERT_EQ(f.levels(), 3);
  ASSERT_NE(f.tempering(), nullptr);
  EXPECT_EQ(LevelFamily::featureCount(s), 3);
  EXPECT_DOUBLE_EQ(f.temperature(1), 10.0);
  EXPECT_FLOAT_EQ(f.tempering()->scale[2], 10.0f);  // sqrt(T)
  for (int k = 0; k < 3; ++k)
    for (int n = 0; n < kPathClassCount; ++n) EXPECT_TRUE(f.estimates(k, n));
  // Features are the targets themselves; the mean of I is level 0's.
  const double features[3] = {1.0, 2.0, 3.0};
  double q[3];
  f.targets(features, q);
  EXPECT_EQ(q[1], 2.0);
  EXPECT_DOUBLE_EQ(LevelFamily::meanTarget(s, {1.0, 5.0, 9.0, 3.0, 5.0, 9.0}), 2.0);
}

TEST(TemperedFamily, PathFeaturesAreItsLevelTargetsAndNothingForANonFinitePath) {
  FamilySettings s;
  s.kind = FamilyKind::Tempered;
  s.levels = 2;
  const LevelFamily f(s, 1.0);
  PathSample p;
  p.add({0.5f, 0.5f}, Color(1.0f), PathClass::L1);
  const std::vector<double> levelTargets = {1.0, std::numeric_limits<double>::infinity()};
  double features[2];
  EXPECT_TRUE(f.features(p, levelTargets, features));
  EXPECT_EQ(features[0], 1.0);
  EXPECT_EQ(features[1], 0.0);  // a non-finite tempered value loses that level only
  p.add({0.5f, 0.5f}, Color(NAN), PathClass::L2);
  EXPECT_FALSE(f.features(p, levelTargets, features));
  EXPECT_EQ(features[0], 0.0);
}

TEST(TemperedFamily, RegularisationShrinksAsAPowerLawInStepsOfAtLeastOnePercent) {
  FamilySettings s;
  s.kind = FamilyKind::Tempered;
  s.regularisation = 0.1;
  s.regularisationDecay = 0.5;
  LevelFamily f(s, 1.0);
  EXPECT_FLOAT_EQ(f.tempering()->minAlpha, 0.1f);    // reg(0) = rho_0
  EXPECT_FALSE(f.setRegularisationStep(0));
  EXPECT_FALSE(f.setRegularisationStep(0));           // (1 + n)^-gamma barely moved: no new targets
  EXPECT_TRUE(f.setRegularisationStep(3));            // 0.1 / 2
  EXPECT_FLOAT_EQ(f.tempering()->minAlpha, 0.05f);
  EXPECT_FALSE(f.setRegularisationStep(3));
  s.regularisation = 0.0;
  LevelFamily off(s, 1.0);
  EXPECT_FALSE(off.setRegularisationStep(100));
  EXPECT_EQ(off.tempering()->minAlpha, 0.0f);
}
