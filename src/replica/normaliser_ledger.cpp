#include "replica/normaliser_ledger.h"

#include <algorithm>

namespace relt {

NormaliserLedger::NormaliserLedger(int levels) : bootstrapSum_(size_t(levels), 0.0), largeSum_(size_t(levels), 0.0) {}

void NormaliserLedger::addBootstrapSample(const double* targets) {
  for (size_t k = 0; k < bootstrapSum_.size(); ++k) bootstrapSum_[k] += targets[k];
}

void NormaliserLedger::bootstrapDone(double samples) { bootstrapCount_ = bootstrapSamples_ = samples; }

void NormaliserLedger::addLargeSteps(std::span<const double> sums, double count) {
  for (size_t k = 0; k < largeSum_.size(); ++k) largeSum_[k] += sums[k];
  largeCount_ += count;
}

void NormaliserLedger::targetsMoved() {
  ++epoch_;
  std::fill(bootstrapSum_.begin(), bootstrapSum_.end(), 0.0);
  bootstrapCount_ = 0.0;
  std::fill(largeSum_.begin(), largeSum_.end(), 0.0);
  largeCount_ = 0.0;
}

std::optional<std::vector<double>> NormaliserLedger::normalisers() const {
  const double n = samples();
  if (!(n > 0.0)) return std::nullopt;
  std::vector<double> b(bootstrapSum_.size());
  for (size_t k = 0; k < b.size(); ++k) b[k] = (bootstrapSum_[k] + largeSum_[k]) / n;
  return b;
}

void NormaliserLedger::restore(State state) {
  bootstrapSamples_ = state.bootstrapSamples;
  epoch_ = state.epoch;
  bootstrapSum_ = std::move(state.bootstrapSum);
  bootstrapCount_ = state.bootstrapCount;
  largeSum_ = std::move(state.largeSum);
  largeCount_ = state.largeCount;
}

}  // namespace relt
