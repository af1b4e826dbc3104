#pragma once
// The decisions of meb's chain pair (thesis digest §5.3), pure functions of target values: the
// visibility chain targets pi_vis = 1[C > 0], the contribution chain pi_con = lum(C), where C is
// the light subpath's contribution list (meb_contribution.h).
#include <cstdint>

#include "mcmc/metropolis.h"

namespace relt {

// b_vis and b_con: the mean of each target over primary sample space.
struct MebNormalisers {
  double visibility = 1.0, contribution = 1.0;
};

inline double visibilityTarget(double contribution) { return contribution > 0.0 ? 1.0 : 0.0; }

// Replica exchange of the two current states (Eq. 4.11): min(1, pi_vis(x_con) pi_con(x_vis) /
// (pi_vis(x_vis) pi_con(x_con))), given lum(C) of the visibility chain's and the contribution
// chain's state. When both are visible it is min(1, lum(C_vis) / lum(C_con)).
inline double mebExchangeAcceptance(double visState, double conState) {
  return acceptance(visibilityTarget(visState) * conState, visibilityTarget(conState) * visState);
}

// A state of either chain with lum(C) = `contribution` splats C times this. Each chain takes half
// of the iteration's N light subpaths, and chain c's sample is weighted by w_c = (pi_c / b_c) /
// (pi_vis / b_vis + pi_con / b_con) (Eq. 6.5) and scaled by b_c / pi_c, so N / (N / 2) w_c b_c /
// pi_c = 2 / (pi_vis / b_vis + pi_con / b_con), the same for both chains. With other normalisers
// b' in w_c than the b that scales the chain, the chain's film is scaled by b_c / b'_c afterwards.
inline double mebSplatScale(double contribution, const MebNormalisers& b) {
  const double vis = visibilityTarget(contribution);
  return vis > 0.0 ? 2.0 / (vis / b.visibility + contribution / b.contribution) : 0.0;
}

// Running sums of both targets over independent uniform samples (the initial set and the large
// steps): their means estimate b_vis and b_con (Eq. 6.4).
struct NormaliserSums {
  double visibility = 0.0, contribution = 0.0;
  uint64_t samples = 0;

  void add(double c) {
    visibility += visibilityTarget(c);
    contribution += c;
    ++samples;
  }
  void add(const NormaliserSums& o) {
    visibility += o.visibility;
    contribution += o.contribution;
    samples += o.samples;
  }
  MebNormalisers mean() const {
    if (!samples) return {};
    return {visibility / double(samples), contribution / double(samples)};
  }
};

}  // namespace relt
