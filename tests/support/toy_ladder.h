#pragma once
// A ladder of Metropolis chains on a toy family of targets over [0,1]^D, one chain per level, with
// an exchange move after each sweep of mutations: the harness of the exchange-move tests (the
// synthetic benchmark of thesis Sec. 5.3.7 and the per-level marginal tests).
#include <functional>
#include <vector>

#include "core/rng.h"
#include "replica/exchange.h"

namespace relt::test {

using ToyPoint = std::vector<double>;
// Fills q[k] = q_k(u) for every level k.
using ToyTargets = std::function<void(const ToyPoint& u, std::vector<double>& q)>;
// Proposes v from u (symmetric), given the level the chain is at.
using ToyProposal = std::function<void(const ToyPoint& u, ToyPoint& v, int level, Rng& rng)>;
// An exchange: matrix and round in, from[] out (exchangeLevels or a deliberately wrong one).
using ToyExchange = std::function<std::vector<int>(const TargetMatrix& q, uint64_t round, Rng& rng)>;

class ToyLadder {
 public:
  // starts[k] is level k's first state.
  ToyLadder(ToyTargets targets, ToyProposal proposal, std::vector<ToyPoint> starts, uint64_t key);

  int levels() const { return static_cast<int>(states_.size()); }
  // One Metropolis step of every level's chain.
  void mutate();
  // One exchange move; returns from[] as the move gave it.
  std::vector<int> exchange(const ToyExchange& move);
  const ToyPoint& state(int level) const { return states_[size_t(level)]; }
  uint64_t rounds() const { return round_; }

 private:
  ToyTargets targets_;
  ToyProposal proposal_;
  std::vector<ToyPoint> states_;
  std::vector<std::vector<double>> q_;  // q_[k] = all levels' targets on level k's state
  Rng rng_;
  uint64_t round_ = 0;
};

// The exchange move of the renderer with the given options.
ToyExchange standardExchange(const ExchangeOptions& options);

// Kelemen's mutation on each coordinate (small step with sizes s1, s2; large step with
// probability pLarge), as the renderer's chains use it.
ToyProposal kelemenProposal(double pLarge);

}  // namespace relt::test
