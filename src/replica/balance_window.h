#pragma once
// When relt decides a group's placement again, and from what: per group of ladders, every rank's
// stepping seconds (and their squares) summed since the group's last decision, over how many
// rounds. A decision is due once the slowest rank has stepped the group for a window long enough
// that timing noise is small (load_balance.h's noiseGain judges what is left). The first windows
// are 1/8, 1/4 and 1/2 of it: an uneven start costs less. A decision that moves nothing keeps
// measuring, its window doubled, up to 8 windows: the noise falls as 1 / sqrt(rounds), so an
// imbalance too small for one window is still found. The same on every rank (same read-backs).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace relt {

class BalanceWindows {
 public:
  // `seconds`: the balance window (--balance-window; 0: never decide).
  BalanceWindows(int groups, int ranks, double seconds);

  // A round of `group` read back: every rank's stepping seconds in it. `timed`: they are timings
  // (rounds restored from a checkpoint carry none and do not count as rounds).
  void addRound(int group, const std::vector<double>& seconds, bool timed);
  // Whether the group's placement is to be decided now: with `ranks` > 1, after the slowest rank
  // stepped it long enough. `groups`: the groups taking turns (a group runs every groups-th round).
  bool due(int group, int groups) const;
  // The decision was taken: it moved chains (a new window starts) or not (measuring goes on over a
  // window twice as long, up to 8 windows).
  void decided(int group, bool moved);

  const std::vector<double>& seconds(int group) const { return seconds_[size_t(group)]; }
  const std::vector<double>& squares(int group) const { return squares_[size_t(group)]; }
  double rounds(int group) const { return rounds_[size_t(group)]; }

 private:
  double window_;
  int ranks_;
  std::vector<std::vector<double>> seconds_, squares_;  // per group, per rank
  std::vector<double> rounds_;                          // per group
  std::vector<uint64_t> decisions_;                     // per group
  std::vector<double> span_;                            // per group: windows the measurement may last (1 to 8)
};

}  // namespace relt
