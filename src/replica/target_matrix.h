#pragma once
// The targets of one ladder's levels evaluated on the states its chains hold (DESIGN §3.5):
// Q(i, j) = q_i(state held by level j). Exchange moves read nothing else; normalisers cancel in
// every ratio they form.
#include <cstddef>
#include <utility>
#include <vector>

namespace relt {

class TargetMatrix {
 public:
  explicit TargetMatrix(int levels) : m_(levels), q_(static_cast<size_t>(levels) * levels, 0.0) {}

  int levels() const { return m_; }
  double operator()(int level, int state) const { return q_[index(level, state)]; }
  double& operator()(int level, int state) { return q_[index(level, state)]; }

  // States j and k change levels: every level's targets on them change places (columns swap).
  void swapStates(int j, int k) {
    for (int i = 0; i < m_; ++i) std::swap((*this)(i, j), (*this)(i, k));
  }

 private:
  size_t index(int level, int state) const { return static_cast<size_t>(level) * m_ + state; }
  int m_;
  std::vector<double> q_;
};

// Metropolis acceptance of exchanging the states of levels i and j (seed 000 Eq. 9):
// min(1, Q(i,j) Q(j,i) / (Q(i,i) Q(j,j))). Never towards a zero or non-finite product; always
// away from a zero one.
double swapAcceptance(const TargetMatrix& q, int i, int j);

}  // namespace relt
