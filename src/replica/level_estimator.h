#pragma once
// The image estimator of a ladder: every level's samples contribute through multiple importance
// sampling over levels (DESIGN §3.3; seed 000 Eq. 22-23, thesis Eq. 5.13). A splat of class n with
// value F, from a state u held by level k, with expected-value weight e, adds
//
//   e * c[k][n] * (q_k(u)/b_k)^(beta-1) * F / sum_l c[l][n] (q_l(u)/b_l)^beta
//
// to the film; beta = 1 is the balance heuristic, beta = 2 the power heuristic. With N steps per
// level the pixel is (film area / N) times the film sum.
#include <array>
#include <vector>

#include "film/film.h"
#include "replica/family.h"

namespace relt {

class LevelEstimator {
 public:
  LevelEstimator(const LevelFamily& family, double beta) : family_(family), beta_(beta) {}

  // The normalisers b_k used by the weights (frozen between rounds so every rank uses the same).
  void setNormalisers(const std::vector<double>& b) { b_ = b; }
  const std::vector<double>& normalisers() const { return b_; }

  // Adds the splats of a state (targets q of every level) held by `level`, with weight e, to a
  // film (or anything with Film's addSplat: a SplatLog).
  template <class Sink>
  void splat(const PathSample& sample, const double* q, int level, double e, Sink& film) const {
    if (!(e > 0.0) || sample.splats.empty()) return;
    std::array<double, kPathClassCount> factor;
    for (int n = 0; n < kPathClassCount; ++n) factor[size_t(n)] = e * classFactor(q, level, n);
    for (const Splat& s : sample.splats) {
      const double f = factor[static_cast<size_t>(s.cls)];
      if (f > 0.0) film.addSplat(s.film, s.value, f);
    }
  }
  // The factor a class-n splat of that state is multiplied by (before e); 0 if level k does not
  // estimate class n.
  double classFactor(const double* q, int level, int cls) const;

 private:
  const LevelFamily& family_;
  double beta_;
  std::vector<double> b_;
};

}  // namespace relt
