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

size_t Distribution1D::sample(float u, float* uRemapped) const {
  const double target = static_cast<double>(u) * total_;
  // First index whose upper CDF bound exceeds the target, skipping zero-weight entries.
  auto it = std::upper_bound(cdf_.begin() + 1, cdf_.end(), target);
  size_t i = std::min(static_cast<size_t>(it - cdf_.begin() - 1), pmf_.size() - 1);
  while (pmf_[i] == 0.0f && i > 0) --i;
  if (uRemapped) {
    const double width = cdf_[i + 1] - cdf_[i];
    const double r = width > 0.0 ? (target - cdf_[i]) / width : 0.0;
    *uRemapped = static_cast<float>(std::clamp(r, 0.0, 0x1.fffffep-1));
  }
  return i;
}

}  // namespace relt
