#pragma once
// Pure decisions of the Markov-chain render loop: chains advance in rounds of the same number of
// steps, a render with a mutation budget gives each chain its share, a timed one stops at a round
// boundary, and snapshots are taken only between rounds. The MPI layer feeds these the elapsed
// times it agreed on, so every rank decides the same.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "mcmc/pssmlt.h"
#include "schedule/schedule.h"

namespace relt {

class RoundSchedule {
 public:
  // One round is one mutation per pixel over all chains. Without a time budget the render makes
  // totalMutations steps in all, chain c its share chainMutations(total, chains, c).
  RoundSchedule(double filmArea, int chains, std::optional<double> seconds, uint64_t totalMutations)
      : chains_(chains),
        perRound_(std::max<uint64_t>(1, static_cast<uint64_t>(std::llround(filmArea / chains)))),
        seconds_(seconds),
        total_(totalMutations) {}

  // Steps chain c has taken after `rounds` rounds.
  uint64_t doneAfter(uint64_t rounds, int chain) const {
    const uint64_t r = rounds * perRound_;
    return seconds_ ? r : std::min(r, chainMutations(total_, chains_, chain));
  }
  // Steps of all chains after `rounds` rounds.
  uint64_t mutationsAfter(uint64_t rounds) const {
    uint64_t n = 0;
    for (int c = 0; c < chains_; ++c) n += doneAfter(rounds, c);
    return n;
  }
  // Whether round `rounds + 1` runs: mutations left, or (timed) expected to end within the budget
  // given the agreed elapsed time and the last round's duration. The first round always runs.
  bool anotherRound(uint64_t rounds, double elapsed, double lastRound) const {
    if (seconds_) return startAnotherPass(static_cast<int>(std::min<uint64_t>(rounds, 1)), elapsed, lastRound, *seconds_);
    return mutationsAfter(rounds) < total_;
  }
  // Fraction done, for the progress line.
  double fraction(uint64_t rounds, double elapsed) const {
    return seconds_ ? std::min(1.0, elapsed / *seconds_) : double(mutationsAfter(rounds)) / double(total_);
  }

 private:
  int chains_;
  uint64_t perRound_;
  std::optional<double> seconds_;
  uint64_t total_;
};

// After a round: a snapshot is due when `every` seconds passed since the last one and another
// round follows (the final image is written anyway).
inline bool snapshotDue(double every, double elapsed, double lastSnapshot, bool anotherRoundFollows) {
  return every > 0.0 && elapsed - lastSnapshot >= every && anotherRoundFollows;
}

}  // namespace relt
