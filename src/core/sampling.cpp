#include "core/sampling.h"

#include <algorithm>

namespace relt {

Distribution1D::Distribution1D(const std::vector<double>& weights) {
  cdf_.resize(weights.size() + 1, 0.0);
  for (size_t i = 0; i < weights.size(); ++i) cdf_[i + 1] = cdf_[i] + std::max(0.0, weights[i]);
  total_ = cdf_.back();
  pmf_.resize(weights.size(), 0.0f);
  if (total_ > 0.0)
    for (size_t i = 0; i < weights.size(); ++i) pmf_[i] = static_cast<float>(std::max(0.0, weights[i]) / total_);
}

float Distribution1D::remap(double target, size_t i) const {
  const double width = cdf_[i + 1] - cdf_[i];
  const double r = width > 0.0 ? (target - cdf_[i]) / width : 0.0;
  return static_cast<float>(std::clamp(r, 0.0, 0x1.fffffep-1));
}

}  // namespace relt
