#include "replica/level_estimator.h"

#include <array>
#include <cmath>

namespace relt {

double LevelEstimator::classFactor(const double* q, int level, int cls) const {
  if (!family_.estimates(level, cls)) return 0.0;
  auto density = [&](int l) {
    const double p = b_[size_t(l)] > 0.0 ? q[l] / b_[size_t(l)] : 0.0;
    return beta_ == 1.0 ? p : std::pow(p, beta_);
  };
  double sum = 0.0;
  for (int l = 0; l < family_.levels(); ++l)
    if (family_.estimates(l, cls)) sum += density(l);
  if (!(sum > 0.0)) return 0.0;
  const double own = b_[size_t(level)] > 0.0 ? q[level] / b_[size_t(level)] : 0.0;
  return (beta_ == 1.0 ? 1.0 : std::pow(own, beta_ - 1.0)) / sum;
}

}  // namespace relt
