#pragma once
// Pure decisions of the replica render loop: every chain takes the same number of steps per round
// (the exchange interval), so every level gets the same number of samples. A mutation budget
// fixes the steps per chain; a time budget stops at a round boundary the ranks agree on.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "schedule/schedule.h"

namespace relt {

class ReplicaSchedule {
 public:
  // mutationsPerPixel * film area steps in all, shared evenly by `chains` chains (rounded up).
  ReplicaSchedule(double filmArea, int chains, int interval, std::optional<double> seconds, double mutationsPerPixel)
      : interval_(std::max(1, interval)),
        seconds_(seconds),
        stepsPerChain_(static_cast<uint64_t>(std::ceil(mutationsPerPixel * filmArea / std::max(1, chains)))) {}

  // A render resumed from a checkpoint taken after `rounds` rounds and `steps` steps per chain
  // (fewer than rounds x interval when the render it continues ended with a short round).
  void resumeAt(uint64_t rounds, uint64_t steps) {
    startRound_ = rounds;
    startSteps_ = steps;
  }

  // Steps each chain takes in round `round` (0-based).
  uint64_t stepsInRound(uint64_t round) const { return stepsAfter(round + 1) - stepsAfter(round); }
  // Steps each chain has taken after `rounds` rounds.
  uint64_t stepsAfter(uint64_t rounds) const {
    const uint64_t r = rounds <= startRound_ ? startSteps_ : startSteps_ + (rounds - startRound_) * uint64_t(interval_);
    return seconds_ ? r : std::min(r, std::max(stepsPerChain_, startSteps_));
  }
  // Whether round `rounds + 1` runs (see RoundSchedule::anotherRound).
  bool anotherRound(uint64_t rounds, double elapsed, double lastRound) const {
    if (seconds_) return startAnotherPass(static_cast<int>(std::min<uint64_t>(rounds, 1)), elapsed, lastRound, *seconds_);
    return stepsAfter(rounds) < stepsPerChain_;
  }
  double fraction(uint64_t rounds, double elapsed) const {
    return seconds_ ? std::min(1.0, elapsed / *seconds_) : double(stepsAfter(rounds)) / double(stepsPerChain_);
  }

 private:
  int interval_;
  std::optional<double> seconds_;
  uint64_t stepsPerChain_;
  uint64_t startRound_ = 0, startSteps_ = 0;
};

// Film sums -> pixels: with N steps per level the pixel is film area / N times the sum; as the
// divisor Renderer::resolve takes.
inline double replicaResolveDivisor(uint64_t stepsPerChain, int ladders, double filmArea) {
  return double(stepsPerChain) * ladders / filmArea;
}

}  // namespace relt
