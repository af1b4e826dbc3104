#include "replica/balance_window.h"

#include <algorithm>

namespace relt {

BalanceWindows::BalanceWindows(int groups, int ranks, double seconds)
    : window_(seconds),
      ranks_(ranks),
      seconds_(size_t(groups), std::vector<double>(size_t(ranks), 0.0)),
      squares_(seconds_),
      rounds_(size_t(groups), 0.0),
      decisions_(size_t(groups), 0),
      span_(size_t(groups), 1.0) {}

void BalanceWindows::addRound(int group, const std::vector<double>& seconds, bool timed) {
  std::vector<double>& sum = seconds_[size_t(group)];
  std::vector<double>& squares = squares_[size_t(group)];
  for (size_t r = 0; r < seconds.size(); ++r) {
    sum[r] += seconds[r];
    squares[r] += seconds[r] * seconds[r];
  }
  if (timed) rounds_[size_t(group)] += 1.0;
}

bool BalanceWindows::due(int group, int groups) const {
  if (!(window_ > 0.0) || ranks_ < 2) return false;
  const std::vector<double>& sum = seconds_[size_t(group)];
  const double slowest = *std::max_element(sum.begin(), sum.end());
  const uint64_t decisions = decisions_[size_t(group)];
  const double needed = span_[size_t(group)] * window_ / double(1 << std::max(0, 3 - int(decisions)));
  return slowest * groups >= needed;
}

void BalanceWindows::decided(int group, bool moved) {
  ++decisions_[size_t(group)];
  double& span = span_[size_t(group)];
  if (!moved && span < 8.0) {
    span *= 2.0;
    return;
  }
  span = 1.0;
  std::fill(seconds_[size_t(group)].begin(), seconds_[size_t(group)].end(), 0.0);
  std::fill(squares_[size_t(group)].begin(), squares_[size_t(group)].end(), 0.0);
  rounds_[size_t(group)] = 0.0;
}

}  // namespace relt
