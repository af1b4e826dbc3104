// What relt's level normalisers rest on (replica/normaliser_ledger.h).
#include "replica/normaliser_ledger.h"

#include <gtest/gtest.h>

namespace relt {
namespace {

TEST(NormaliserLedger, NormalisersAreTheMeanTargetsOfTheBootstrapAndTheLargeSteps) {
  NormaliserLedger ledger(2);
  EXPECT_FALSE(ledger.normalisers());
  const double a[] = {1.0, 4.0}, b[] = {3.0, 0.0};
  ledger.addBootstrapSample(a);
  ledger.addBootstrapSample(b);
  ledger.bootstrapDone(2.0);
  EXPECT_EQ(*ledger.normalisers(), (std::vector<double>{2.0, 2.0}));
  EXPECT_EQ(ledger.bootstrapSum(1), 4.0);
  const std::vector<double> large = {8.0, 2.0};
  ledger.addLargeSteps(large, 2.0);
  EXPECT_EQ(*ledger.normalisers(), (std::vector<double>{3.0, 1.5}));
  EXPECT_EQ(ledger.samples(), 4.0);
  EXPECT_FALSE(ledger.fewSamplesSinceMove());
}

TEST(NormaliserLedger, MovedTargetsStartAfreshUntilABootstrapsWorthOfLargeSteps) {
  NormaliserLedger ledger(1);
  const double q[] = {5.0};
  for (int i = 0; i < 4; ++i) ledger.addBootstrapSample(q);
  ledger.bootstrapDone(4.0);
  ledger.targetsMoved();
  EXPECT_EQ(ledger.epoch(), 1u);
  EXPECT_FALSE(ledger.normalisers());  // nothing under the new targets yet: the old ones stay
  EXPECT_TRUE(ledger.fewSamplesSinceMove());
  const std::vector<double> large = {6.0};
  ledger.addLargeSteps(large, 3.0);
  EXPECT_EQ(*ledger.normalisers(), (std::vector<double>{2.0}));
  EXPECT_TRUE(ledger.fewSamplesSinceMove());
  ledger.addLargeSteps(large, 1.0);
  EXPECT_FALSE(ledger.fewSamplesSinceMove());  // 4 large steps, as many as the bootstrap had
}

TEST(NormaliserLedger, ItsStateRestoresExactly) {
  NormaliserLedger ledger(2), restored(2);
  const double q[] = {0.1, 0.7};
  ledger.addBootstrapSample(q);
  ledger.bootstrapDone(1.0);
  ledger.targetsMoved();
  const std::vector<double> large = {0.3, 0.9};
  ledger.addLargeSteps(large, 1.0);
  restored.restore(ledger.state());
  EXPECT_EQ(restored.normalisers(), ledger.normalisers());
  EXPECT_EQ(restored.epoch(), 1u);
  EXPECT_EQ(restored.fewSamplesSinceMove(), ledger.fewSamplesSinceMove());
  EXPECT_EQ(restored.samples(), ledger.samples());
}

}  // namespace
}  // namespace relt
