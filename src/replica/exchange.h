#pragma once
// Exchange moves between the levels of one ladder (DESIGN §3.5, thesis ch. 5.3 and App. 5.B): pure
// functions from the target matrix and a random stream to the new assignment of states to
// levels. Every rank runs them on the same gathered matrix with the same per-ladder stream, so all
// ranks agree without further messages.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/rng.h"
#include "replica/target_matrix.h"

namespace relt {

enum class ExchangeMove {
  Neighbour,    // Metropolis swaps (seed 000 Eq. 9) of every adjacent pair, from the top down
  Deo,          // deterministic even-odd: all even pairs on even rounds, odd pairs on odd rounds
  Permutation,  // importance-sampled permutation of all states, always accepted (M <= 12)
  Swap,         // importance-sampled swap partner per level, with the Eq. 5.11 acceptance
  Eem,          // frequent equi-energy moves: swaps within log-spaced rings of the level-0 target
};
std::optional<ExchangeMove> parseExchangeMove(std::string_view name);
const char* exchangeMoveName(ExchangeMove move);

// Exchange attempts and acceptances between pairs of levels, for diagnostics. For the pairwise
// moves a pair counts when it is proposed; for permutations every adjacent pair counts each round
// and is "accepted" when a state moved between the two levels.
struct ExchangeTally {
  explicit ExchangeTally(int m = 0)
      : levels(m), proposed(size_t(m) * m, 0), accepted(size_t(m) * m, 0), changed(size_t(m), 0), rounds(0) {}
  int levels;
  std::vector<uint64_t> proposed, accepted;  // [min(i,j) * levels + max(i,j)]
  std::vector<uint64_t> changed;             // rounds after which level k held another state
  uint64_t rounds;

  void count(int i, int j, bool accept);
  void add(const ExchangeTally& other);
  // Acceptance of exchanges between levels k and k + 1 (NaN when never proposed).
  double adjacentAcceptance(int k) const;
  // Fraction of rounds after which level k held a different state (the thesis's "swap rate").
  double changeRate(int k) const;
};

struct ExchangeOptions {
  ExchangeMove move = ExchangeMove::Deo;
  int energyRings = 0;  // eem: rings over the ladder's range of level-0 targets; 0 = one per level
};

// The new assignment: from[i] = the level whose state level i holds after the move (the identity
// when nothing moves). `round` is the exchange round (deo alternates on it); `rng` is the ladder's
// stream for this round.
std::vector<int> exchangeLevels(const ExchangeOptions& options, const TargetMatrix& q, uint64_t round, Rng& rng,
                                ExchangeTally* tally = nullptr);

// Counts round trips of states through a ladder: a state that was at level 0, then reached level
// M-1, completes a trip on its next return to level 0.
class RoundTrips {
 public:
  RoundTrips(int chains, int levels) : levels_(levels), phase_(size_t(chains), Phase::Unseen), trips_(size_t(chains), 0) {}
  // Chain c now holds `level`.
  void visit(int chain, int level);
  uint64_t trips(int chain) const { return trips_[size_t(chain)]; }
  uint64_t total() const;
  // Trips counted before a checkpoint this render resumed from (part of total()).
  void addEarlier(uint64_t trips) { earlier_ += trips; }
  // Where chain c is in its trip (moves with the chain when only its host tracks it).
  uint8_t phase(int chain) const { return static_cast<uint8_t>(phase_[size_t(chain)]); }
  void setPhase(int chain, uint8_t phase) { phase_[size_t(chain)] = static_cast<Phase>(phase); }

 private:
  enum class Phase : uint8_t { Unseen, SeenBottom, ReachedTop };
  int levels_;
  std::vector<Phase> phase_;
  std::vector<uint64_t> trips_;
  uint64_t earlier_ = 0;
};

}  // namespace relt
