#pragma once
// Metropolis-Hastings acceptance for symmetric proposals (thesis digest §2.2).
#include <algorithm>
#include <cmath>
#include <utility>

#include "pss/primary_sample_vector.h"

namespace relt {

// a = min(1, target(proposal) / target(current)); a state of zero target is left at once (a = 1).
// A proposal with a zero, negative or non-finite target is never accepted.
template <class Real>
inline Real acceptance(Real current, Real proposal) {
  if (!(proposal > Real(0)) || !std::isfinite(proposal)) return Real(0);
  if (!(current > Real(0))) return Real(1);
  return std::min(Real(1), proposal / current);
}

// The Metropolis decision taken: an accepted proposal becomes the current state (u keeps its
// proposed coordinates), a rejected one is dropped (u goes back). Returns `accepted`.
template <class State>
inline bool keepOrRevert(bool accepted, PrimarySampleVector& u, State& current, State& proposal) {
  if (accepted) {
    u.accept();
    std::swap(current, proposal);
  } else {
    u.reject();
  }
  return accepted;
}

}  // namespace relt
