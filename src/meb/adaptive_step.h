#pragma once
// meb's small step (thesis digest §2.9, Eq. 6.8) and the adaptation of its size towards a target
// acceptance rate (Eq. 4.10).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "pss/kelemen.h"

namespace relt {

// Eq. 6.8: u moves by (2 xi)^(1/theta) up (xi < 1/2) or by (2 xi - 1)^(1/theta) down, wrapped
// into [0, 1). The displacement's law is the same both ways, so the proposal is symmetric;
// theta -> 0 stays put, theta = 1 proposes a uniform point. Its mean size is theta / (1 + theta).
inline float adaptiveSmallStep(float u, float xi, float theta) {
  const bool up = xi < 0.5f;
  const float x = up ? 2.0f * xi : 2.0f * xi - 1.0f;
  const float d = std::pow(x, 1.0f / theta);
  return wrapUnit(u, up ? d : -d);
}

// Eq. 4.10 on log theta, with gains i^-0.6: log theta_{i+1} = log theta_i + (a_i - A*) / i^0.6,
// a_i the acceptance probability of step i. The thesis adds (A_i - A*) / i to theta itself, which
// from a small theta sends it across its whole range in the first steps; and its chains adapt
// over the whole render, where meb's start again every iteration with a few thousand steps, over
// which gains 1 / i move theta by a factor of at most n^0.23. Gains i^-0.6 still diminish (any
// exponent in (1/2, 1] keeps the chain ergodic, Andrieu and Thoms 2008) and settle theta where
// the acceptance is A* (23.4 %) within a few hundred steps.
class StepSizeAdaptation {
 public:
  // 1/256: a mean step of 0.0039, about Kelemen's default small step (pss/kelemen.h).
  static constexpr double kInitialTheta = 1.0 / 256.0;
  static constexpr double kTargetAcceptance = 0.234;

  explicit StepSizeAdaptation(double theta = kInitialTheta, double target = kTargetAcceptance)
      : logTheta_(std::log(theta)), target_(target) {}

  float theta() const { return float(std::exp(logTheta_)); }
  void record(double acceptance) {
    ++steps_;
    accepted_ += acceptance;
    logTheta_ = std::clamp(logTheta_ + (acceptance - target_) * std::pow(double(steps_), -0.6), kLogThetaMin, 0.0);
  }
  uint64_t steps() const { return steps_; }
  double acceptanceRate() const { return steps_ ? accepted_ / double(steps_) : 0.0; }

 private:
  static constexpr double kLogThetaMin = -16.0;  // theta about 1e-7: below float resolution near 1

  double logTheta_, target_;
  uint64_t steps_ = 0;
  double accepted_ = 0.0;
};

}  // namespace relt
