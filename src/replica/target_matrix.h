#pragma once
// The targets of one ladder's levels evaluated on the states its chains hold (DESIGN §3.5):
// Q(i, j) = q_i(state held by level j) / b_i, normalised by the round's b_i. Exchange moves read
// nothing else. The normalisers cancel in every acceptance ratio; they matter where a move
// chooses among partners (the importance-sampled swap: pi_i(x_k) pi_k(x_i)).
#include <cmath>
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

  // Q(i, j) / b_i for every level with a positive finite normaliser b_i (the others as they are).
  void normaliseRows(const std::vector<double>& b) {
    for (int i = 0; i < m_ && size_t(i) < b.size(); ++i) {
      const double bi = b[size_t(i)];
      if (!(bi > 0.0) || !std::isfinite(bi)) continue;
      for (int j = 0; j < m_; ++j) (*this)(i, j) /= bi;
    }
  }
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
