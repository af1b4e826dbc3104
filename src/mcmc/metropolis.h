#pragma once
// Metropolis-Hastings acceptance for symmetric proposals (thesis digest §2.2).
#include <algorithm>
#include <cmath>

namespace relt {

// a = min(1, target(proposal) / target(current)); a state of zero target is left at once (a = 1).
// A proposal with a zero, negative or non-finite target is never accepted.
inline float acceptance(float current, float proposal) {
  if (!(proposal > 0.0f) || !std::isfinite(proposal)) return 0.0f;
  if (!(current > 0.0f)) return 1.0f;
  return std::min(1.0f, proposal / current);
}

}  // namespace relt
