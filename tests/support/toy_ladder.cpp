#include "toy_ladder.h"

#include "mcmc/metropolis.h"
#include "pss/kelemen.h"

namespace relt::test {

ToyLadder::ToyLadder(ToyTargets targets, ToyProposal proposal, std::vector<ToyPoint> starts, uint64_t key)
    : targets_(std::move(targets)), proposal_(std::move(proposal)), states_(std::move(starts)), rng_(key, 3) {
  q_.resize(states_.size(), std::vector<double>(states_.size()));
  for (size_t k = 0; k < states_.size(); ++k) targets_(states_[k], q_[k]);
}

void ToyLadder::mutate() {
  ToyPoint v;
  std::vector<double> qv(states_.size());
  for (int k = 0; k < levels(); ++k) {
    proposal_(states_[size_t(k)], v, k, rng_);
    targets_(v, qv);
    const double a = acceptance(q_[size_t(k)][size_t(k)], qv[size_t(k)]);
    if (rng_.uniformDouble() < a) {
      states_[size_t(k)] = v;
      q_[size_t(k)] = qv;
    }
  }
}

std::vector<int> ToyLadder::exchange(const ToyExchange& move) {
  const int m = levels();
  TargetMatrix q(m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) q(i, j) = q_[size_t(j)][size_t(i)];
  Rng rng(hashKey(rng_.nextU32(), round_));
  const std::vector<int> from = move(q, round_++, rng);
  std::vector<ToyPoint> states(states_.size());
  std::vector<std::vector<double>> qs(q_.size());
  for (int i = 0; i < m; ++i) {
    states[size_t(i)] = states_[size_t(from[size_t(i)])];
    qs[size_t(i)] = q_[size_t(from[size_t(i)])];
  }
  states_.swap(states);
  q_.swap(qs);
  return from;
}

ToyExchange standardExchange(const ExchangeOptions& options) {
  return [options](const TargetMatrix& q, uint64_t round, Rng& rng) { return exchangeLevels(options, q, round, rng); };
}

ToyProposal kelemenProposal(double pLarge) {
  return [pLarge](const ToyPoint& u, ToyPoint& v, int, Rng& rng) {
    v = u;
    const bool large = rng.uniform() < pLarge;
    const KelemenSizes sizes;
    for (double& x : v) x = large ? rng.uniformDouble() : kelemenSmallStep(static_cast<float>(x), rng.uniform(), sizes);
  };
}

}  // namespace relt::test
