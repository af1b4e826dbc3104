#pragma once
// The wall clock of budgets, progress and timings: steady (never set back), in seconds.
#include <chrono>

namespace relt {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace relt
