#pragma once
// Importance-sampled permutations of a ladder's states (thesis 5.3.2 and App. 5.C; thesis digest
// §4.2): o is drawn with probability proportional to prod_i Q(i, o[i]) over all M! permutations,
// the identity included, so the move is always accepted. A dynamic programme over the 2^M subsets
// of used states makes this O(M 2^M) instead of O(M!).
#include <cstddef>
#include <vector>

#include "core/rng.h"
#include "replica/target_matrix.h"

namespace relt {

inline constexpr int kMaxPermutationLevels = 12;

class PermutationSampler {
 public:
  // Rows are scaled to a maximum of 1 first: every permutation uses each row once, so the
  // distribution is unchanged and the products stay in range.
  explicit PermutationSampler(const TargetMatrix& q);

  // o[i] = the level whose state level i receives. The identity if no permutation has a positive
  // product (a level holding a state of zero target, which chains never accept).
  std::vector<int> sample(Rng& rng) const;
  // Probability of o under the sampler (for tests).
  double probability(const std::vector<int>& o) const;

 private:
  int m_;
  std::vector<double> w_;       // scaled Q, row-major
  std::vector<double> suffix_;  // suffix_[S]: sum over completions of the prefix using states S
  double w(int i, int k) const { return w_[static_cast<size_t>(i) * m_ + k]; }
};

}  // namespace relt
