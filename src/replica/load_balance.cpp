#include "replica/load_balance.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace relt {

std::vector<int> balancedCounts(const std::vector<int>& chains, const std::vector<double>& seconds, double minGain) {
  const size_t ranks = chains.size();
  std::vector<double> speed(ranks, 0.0);  // chains per second; 0: not measured, count kept
  int movable = 0;
  double slowest = 0.0;
  for (size_t r = 0; r < ranks; ++r) {
    if (chains[r] > 0 && seconds[r] > 0.0) {
      speed[r] = chains[r] / seconds[r];
      movable += chains[r];
      slowest = std::max(slowest, seconds[r]);
    }
  }
  if (slowest <= 0.0) return chains;

  // Each measured rank starts with one chain; the rest go one at a time to the rank that would
  // finish earliest with one more (optimal for the slowest rank's time with equal chains).
  std::vector<int> counts = chains;
  using Entry = std::pair<double, size_t>;  // (time with one more chain, rank)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> next;
  for (size_t r = 0; r < ranks; ++r) {
    if (speed[r] <= 0.0) continue;
    counts[r] = 1;
    --movable;
    next.emplace(2.0 / speed[r], r);
  }
  for (; movable > 0; --movable) {
    const size_t r = next.top().second;
    next.pop();
    ++counts[r];
    next.emplace((counts[r] + 1) / speed[r], r);
  }
  double predicted = 0.0;
  for (size_t r = 0; r < ranks; ++r)
    if (speed[r] > 0.0) predicted = std::max(predicted, counts[r] / speed[r]);
  return predicted < (1.0 - minGain) * slowest ? counts : chains;
}

double noiseGain(const std::vector<int>& chains, const std::vector<double>& seconds, const std::vector<double>& squares,
                 double rounds, double floor, double ceiling) {
  double relativeError = 0.0;
  int measured = 0;
  for (size_t r = 0; r < seconds.size(); ++r) {
    if (chains[r] <= 0 || !(seconds[r] > 0.0)) continue;
    ++measured;
    const double mean = seconds[r] / rounds;
    const double variance = std::max(0.0, squares[r] / rounds - mean * mean);
    relativeError = std::max(relativeError, std::sqrt(variance * rounds) / seconds[r]);
  }
  if (measured < 2) return floor;
  if (rounds < 4.0) return std::max(floor, ceiling);  // too few rounds to measure a spread
  const double z = std::sqrt(2.0 * std::log(double(measured))) + 1.0;
  return std::clamp(z * relativeError, floor, std::max(floor, ceiling));
}

std::vector<ChainMove> planMoves(const std::vector<std::vector<int>>& hosted, const std::vector<int>& counts) {
  std::vector<ChainMove> moves;
  size_t to = 0;
  int received = 0;  // by rank `to` so far
  for (size_t from = 0; from < hosted.size(); ++from) {
    const std::vector<int>& mine = hosted[from];
    for (size_t i = size_t(std::max(counts[from], 0)); i < mine.size(); ++i) {
      while (to < hosted.size() && int(hosted[to].size()) + received >= counts[to]) {
        ++to;
        received = 0;
      }
      if (to == hosted.size()) return moves;  // counts sum to fewer chains than hosted: keep the rest
      moves.push_back({mine[i], int(from), int(to)});
      ++received;
    }
  }
  return moves;
}

std::vector<std::vector<int>> applyMoves(const std::vector<std::vector<int>>& hosted, const std::vector<ChainMove>& moves) {
  std::vector<std::vector<int>> out = hosted;
  for (const ChainMove& m : moves) {
    std::vector<int>& from = out[size_t(m.from)];
    from.erase(std::find(from.begin(), from.end(), m.chain));
    out[size_t(m.to)].push_back(m.chain);
  }
  return out;
}

}  // namespace relt
