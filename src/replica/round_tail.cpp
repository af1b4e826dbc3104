#include "replica/round_tail.h"

#include <stdexcept>

namespace relt {
namespace {

// The requests travel as one number: bit 0 stop, bit 1 save.
double requestBits(bool stop, bool save) { return (stop ? 1.0 : 0.0) + (save ? 2.0 : 0.0); }

}  // namespace

void appendRoundTail(const RoundTail& tail, std::vector<double>& message) {
  message.insert(message.end(), tail.largeSums.begin(), tail.largeSums.end());
  message.push_back(tail.largeCount);
  message.push_back(tail.seconds);
  message.push_back(requestBits(tail.stop, tail.save));
  message.push_back(tail.elapsed);
}

std::span<const double> roundTailOf(std::span<const double> message, int levels, bool active) {
  const size_t n = roundTailLength(levels, active);
  if (message.size() < n) throw std::logic_error("a round message shorter than its tail");
  return message.last(n);
}

RoundTail readRoundTail(std::span<const double> message, int levels, bool active) {
  const std::span<const double> t = roundTailOf(message, levels, active);
  const size_t sums = t.size() - 4;
  RoundTail tail;
  tail.largeSums = t.first(sums);
  tail.largeCount = t[sums];
  tail.seconds = t[sums + 1];
  const int bits = int(t[sums + 2]);
  tail.stop = (bits & 1) != 0;
  tail.save = (bits & 2) != 0;
  tail.elapsed = t[sums + 3];
  return tail;
}

}  // namespace relt
