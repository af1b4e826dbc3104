#pragma once
// Placement follows measured speed. Every level must take the same number of steps per round, so a
// slow rank (a busier node, a slower core) holds every other rank at the round's collective. The
// chains are alike on average (their levels rotate through exchanges), so a rank's speed is
// chains hosted / seconds stepping them, and giving each rank chains in proportion to its speed
// makes the ranks finish together. Chain states move; the image does not change (chains are keyed
// by their global id, not by their rank). Pure functions: every rank runs them on the same
// gathered timings and gets the same plan.
#include <vector>

namespace relt {

// New chain counts per rank from the counts and the seconds each rank spent stepping them over
// the same rounds. A rank with chains keeps at least one (its speed stays measured); a rank without
// chains or timings keeps its count. Returns `chains` unchanged unless the slowest rank's predicted
// time falls by more than `minGain` (a fraction), so noise does not move chains back and forth.
std::vector<int> balancedCounts(const std::vector<int>& chains, const std::vector<double>& seconds, double minGain);

// The smallest predicted gain worth moving chains for, from what a balance window measured: every
// rank's stepping seconds summed over `rounds` rounds, and their squares. A rank's window time
// carries a relative standard error cv / sqrt(rounds) (cv: the variation of its round times, from
// paths of different lengths); the slowest of P ranks looks slow by about sqrt(2 ln P) of those
// from noise alone. A gain below that plus one more standard error is not told apart from noise,
// and every move makes the two ranks meet, so it costs. Never below `floor`, never above `ceiling`:
// a rank that shares its core loses whole time slices, its round times are heavy-tailed, and the
// error for independent rounds then overstates the noise of a window that holds many slices.
// Fewer than 4 rounds (a rank with many chains can take a whole first window for one round): the
// spread is unknown, the ceiling.
// Only ranks holding chains count (an idle rank's tiny stepping times are all jitter).
double noiseGain(const std::vector<int>& chains, const std::vector<double>& seconds, const std::vector<double>& squares,
                 double rounds, double floor, double ceiling);

struct ChainMove {
  int chain, from, to;
  bool operator==(const ChainMove&) const = default;
};

// Moves that turn `hosted` (global chain ids per rank) into the given counts: ranks with too many
// give away their last chains, in order, to ranks with too few, in rank order.
std::vector<ChainMove> planMoves(const std::vector<std::vector<int>>& hosted, const std::vector<int>& counts);

// `hosted` after the moves: a rank keeps its remaining chains in order and appends those it receives.
std::vector<std::vector<int>> applyMoves(const std::vector<std::vector<int>>& hosted, const std::vector<ChainMove>& moves);

}  // namespace relt
