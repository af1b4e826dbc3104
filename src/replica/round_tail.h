#pragma once
// The tail every rank's round message ends with, read back `lag` rounds later: the round's
// large-step sums per level (only while the replicas are active), their count, the rank's
// stepping seconds, its stop and save requests and its elapsed time. It travels as doubles in the
// round's collective; these are its named fields and the one place that knows their order.
#include <cstddef>
#include <span>
#include <vector>

namespace relt {

struct RoundTail {
  std::span<const double> largeSums;  // one per level; empty when inactive
  double largeCount = 0.0;
  double seconds = 0.0;  // stepping time of the round (0: no timing data, e.g. restored rounds)
  bool stop = false, save = false;
  double elapsed = 0.0;
};

// Numbers in a tail: the levels' sums when active, then four.
inline size_t roundTailLength(int levels, bool active) { return (active ? size_t(levels) : 0) + 4; }

// Appends a tail to `message` (largeSums must hold `levels` numbers when active, none otherwise).
void appendRoundTail(const RoundTail& tail, std::vector<double>& message);

// The last roundTailLength(levels, active) numbers of `message`. Throws std::logic_error on a
// shorter message.
std::span<const double> roundTailOf(std::span<const double> message, int levels, bool active);

// The tail at the end of `message`, which ends with one of roundTailLength(levels, active)
// numbers; its largeSums view `message`. Throws std::logic_error on a shorter message.
RoundTail readRoundTail(std::span<const double> message, int levels, bool active);

}  // namespace relt
