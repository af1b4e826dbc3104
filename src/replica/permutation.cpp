#include "replica/permutation.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace relt {

PermutationSampler::PermutationSampler(const TargetMatrix& q) : m_(q.levels()) {
  if (m_ < 1 || m_ > kMaxPermutationLevels) throw std::invalid_argument("permutation exchange needs 1 to 12 levels");
  w_.resize(static_cast<size_t>(m_) * m_);
  for (int i = 0; i < m_; ++i) {
    double rowMax = 0.0;
    for (int k = 0; k < m_; ++k) {
      const double v = q(i, k);
      if (std::isfinite(v) && v > rowMax) rowMax = v;
    }
    for (int k = 0; k < m_; ++k) {
      const double v = q(i, k);
      w_[static_cast<size_t>(i) * m_ + k] = rowMax > 0.0 && std::isfinite(v) && v > 0.0 ? v / rowMax : 0.0;
    }
  }
  // The prefix that used states S has filled positions 0..|S|-1; position |S| is next. Supersets
  // come first when S runs downwards, since S | bit > S.
  const unsigned full = (1u << m_) - 1u;
  suffix_.assign(size_t{full} + 1, 0.0);
  suffix_[full] = 1.0;
  for (unsigned s = full; s-- > 0;) {
    const int i = std::popcount(s);
    double acc = 0.0;
    for (int k = 0; k < m_; ++k)
      if (!(s & (1u << k))) acc += w(i, k) * suffix_[s | (1u << k)];
    suffix_[s] = acc;
  }
}

std::vector<int> PermutationSampler::sample(Rng& rng) const {
  std::vector<int> o(static_cast<size_t>(m_));
  if (!(suffix_[0] > 0.0)) {
    std::iota(o.begin(), o.end(), 0);
    return o;
  }
  unsigned used = 0;
  for (int i = 0; i < m_; ++i) {
    // A fresh uniform per position has the same distribution as rescaling one and is safer.
    double target = rng.uniformDouble() * suffix_[used];
    int chosen = -1, last = -1;
    for (int k = 0; k < m_; ++k) {
      if (used & (1u << k)) continue;
      const double p = w(i, k) * suffix_[used | (1u << k)];
      if (!(p > 0.0)) continue;
      last = k;
      if (target < p) {
        chosen = k;
        break;
      }
      target -= p;
    }
    if (chosen < 0) chosen = last;  // round-off at the end of the loop
    o[static_cast<size_t>(i)] = chosen;
    used |= 1u << chosen;
  }
  return o;
}

double PermutationSampler::probability(const std::vector<int>& o) const {
  if (!(suffix_[0] > 0.0)) return std::is_sorted(o.begin(), o.end()) ? 1.0 : 0.0;
  double p = 1.0;
  for (int i = 0; i < m_; ++i) p *= w(i, o[static_cast<size_t>(i)]);
  return p / suffix_[0];
}

}  // namespace relt
