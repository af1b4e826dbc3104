#pragma once
// Metropolis-Hastings acceptance for symmetric proposals (thesis digest §2.2).
#include <algorithm>
#include <cmath>

namespace relt {

// a = min(1, target(proposal) / target(current)); a state of zero target is left at once (a = 1).
// A proposal with a zero, negative or non-finite target is never accepted.
template <class Real>
inline Real acceptance(Real current, Real proposal) {
  if (!(proposal > Real(0)) || !std::isfinite(proposal)) return Real(0);
  if (!(current > Real(0))) return Real(1);
  return std::min(Real(1), proposal / current);
}

}  // namespace relt
