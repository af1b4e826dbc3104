#include "replica/exchange.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "replica/permutation.h"

namespace relt {

double swapAcceptance(const TargetMatrix& q, int i, int j) {
  const double proposed = q(i, j) * q(j, i), current = q(i, i) * q(j, j);
  if (!(proposed > 0.0) || !std::isfinite(proposed)) return 0.0;
  if (!(current > 0.0)) return 1.0;
  return std::min(1.0, proposed / current);
}

std::optional<ExchangeMove> parseExchangeMove(std::string_view name) {
  for (ExchangeMove m : {ExchangeMove::Neighbour, ExchangeMove::Deo, ExchangeMove::Permutation, ExchangeMove::Swap,
                         ExchangeMove::Eem})
    if (name == exchangeMoveName(m)) return m;
  return std::nullopt;
}

const char* exchangeMoveName(ExchangeMove move) {
  switch (move) {
    case ExchangeMove::Neighbour: return "neighbour";
    case ExchangeMove::Deo: return "deo";
    case ExchangeMove::Permutation: return "permutation";
    case ExchangeMove::Swap: return "swap";
    case ExchangeMove::Eem: return "eem";
  }
  return "?";
}

void ExchangeTally::count(int i, int j, bool accept) {
  const size_t at = size_t(std::min(i, j)) * levels + std::max(i, j);
  ++proposed[at];
  if (accept) ++accepted[at];
}

void ExchangeTally::add(const ExchangeTally& o) {
  if (levels == 0) *this = ExchangeTally(o.levels);
  for (size_t k = 0; k < proposed.size(); ++k) {
    proposed[k] += o.proposed[k];
    accepted[k] += o.accepted[k];
  }
  for (size_t k = 0; k < changed.size(); ++k) changed[k] += o.changed[k];
  rounds += o.rounds;
}

double ExchangeTally::adjacentAcceptance(int k) const {
  const size_t at = size_t(k) * levels + k + 1;
  return proposed[at] ? double(accepted[at]) / double(proposed[at]) : std::numeric_limits<double>::quiet_NaN();
}

double ExchangeTally::changeRate(int k) const { return rounds ? double(changed[size_t(k)]) / double(rounds) : 0.0; }

namespace {

// The assignment being built: `from` as in exchangeLevels, `q` the matrix with columns following
// the states.
struct Assignment {
  explicit Assignment(const TargetMatrix& matrix) : q(matrix), from(size_t(matrix.levels())) {
    std::iota(from.begin(), from.end(), 0);
  }
  void swap(int i, int j) {
    q.swapStates(i, j);
    std::swap(from[size_t(i)], from[size_t(j)]);
  }
  // A Metropolis swap of levels i and j.
  void trySwap(int i, int j, Rng& rng, ExchangeTally* tally) {
    const bool accept = rng.uniformDouble() < swapAcceptance(q, i, j);
    if (accept) swap(i, j);
    if (tally) tally->count(i, j, accept);
  }
  TargetMatrix q;
  std::vector<int> from;
};

// Importance-sampled swap for level i (thesis Eq. 5.9-5.11): partner k with probability
// proportional to Q(i,k) Q(k,i) of the normalised targets (k = i included), accepted with
// min(1, Z / Z') where Z' is the same sum after the swap.
void importanceSwap(Assignment& a, int i, Rng& rng, ExchangeTally* tally) {
  const int m = a.q.levels();
  auto partnerMass = [&](int k) { return a.q(i, k) * a.q(k, i); };
  double z = 0.0;
  for (int k = 0; k < m; ++k) z += partnerMass(k);
  if (!(z > 0.0) || !std::isfinite(z)) return;
  double target = rng.uniformDouble() * z;
  int j = i;
  for (int k = 0; k < m; ++k) {
    const double p = partnerMass(k);
    if (!(p > 0.0)) continue;
    j = k;
    if (target < p) break;
    target -= p;
  }
  if (j == i) return;
  a.swap(i, j);
  double zAfter = 0.0;
  for (int k = 0; k < m; ++k) zAfter += partnerMass(k);
  const bool accept = rng.uniformDouble() < std::min(1.0, z / zAfter);
  if (!accept) a.swap(i, j);
  if (tally) tally->count(i, j, accept);
}

// Frequent equi-energy moves (thesis 5.3.5, 5.B.3): each level in turn swaps with a uniformly
// chosen level whose state lies in the same energy ring, with the plain swap acceptance. Rings
// split the log range of the ladder's level-0 targets; swaps keep that set, hence the rings and
// their counts, so the partner choice is symmetric.
void equiEnergyMoves(Assignment& a, int rings, Rng& rng, ExchangeTally* tally) {
  const int m = a.q.levels();
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (int j = 0; j < m; ++j) {
    const double e = a.q(0, j);
    if (e > 0.0 && std::isfinite(e)) lo = std::min(lo, e), hi = std::max(hi, e);
  }
  const double span = hi > lo ? std::log(hi / lo) : 1.0;
  auto ringOf = [&](int level) {
    const double e = a.q(0, level);
    if (!(e > 0.0) || !std::isfinite(e)) return -1;
    return std::min(rings - 1, static_cast<int>(rings * std::log(e / lo) / span));
  };
  std::vector<int> partners;
  for (int j = 0; j < m; ++j) {
    partners.clear();
    const int ring = ringOf(j);
    for (int l = 0; l < m; ++l)
      if (l != j && ringOf(l) == ring) partners.push_back(l);
    if (partners.empty()) continue;
    a.trySwap(j, partners[rng.below(static_cast<uint32_t>(partners.size()))], rng, tally);
  }
}

}  // namespace

std::vector<int> exchangeLevels(const ExchangeOptions& options, const TargetMatrix& q, uint64_t round, Rng& rng,
                                ExchangeTally* tally) {
  const int m = q.levels();
  Assignment a(q);
  if (m >= 2) {
    switch (options.move) {
      case ExchangeMove::Neighbour:
        // Top down, so a state found by a flat level can reach level 0 in one exchange.
        for (int k = m - 2; k >= 0; --k) a.trySwap(k, k + 1, rng, tally);
        break;
      case ExchangeMove::Deo:
        for (int k = static_cast<int>(round % 2); k + 1 < m; k += 2) a.trySwap(k, k + 1, rng, tally);
        break;
      case ExchangeMove::Permutation:
        a.from = PermutationSampler(q).sample(rng);
        if (tally)
          for (int k = 0; k + 1 < m; ++k) tally->count(k, k + 1, a.from[size_t(k)] == k + 1 || a.from[size_t(k + 1)] == k);
        break;
      case ExchangeMove::Swap:
        for (int i = 0; i < m; ++i) importanceSwap(a, i, rng, tally);
        break;
      case ExchangeMove::Eem:
        equiEnergyMoves(a, options.energyRings > 0 ? options.energyRings : m, rng, tally);
        break;
    }
  }
  if (tally) {
    for (int k = 0; k < m; ++k)
      if (a.from[size_t(k)] != k) ++tally->changed[size_t(k)];
    ++tally->rounds;
  }
  return a.from;
}

void RoundTrips::visit(int chain, int level) {
  Phase& p = phase_[size_t(chain)];
  if (level == 0) {
    if (p == Phase::ReachedTop) ++trips_[size_t(chain)];
    p = Phase::SeenBottom;
  } else if (level == levels_ - 1 && p == Phase::SeenBottom) {
    p = Phase::ReachedTop;
  }
}

uint64_t RoundTrips::total() const {
  uint64_t n = earlier_;
  for (uint64_t t : trips_) n += t;
  return n;
}

}  // namespace relt
