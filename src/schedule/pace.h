#pragma once
// How long the next pass or round of a timed render is expected to take, from the ones before it.
// A render decides to start another only if it is expected to end within the budget; the last
// duration alone is a poor guess: one pass that spanned a stall (a rank paused or descheduled for
// a moment, a busy machine) would end the render early by many times the stall. The median of the
// recent durations ignores such outliers and still follows a lasting change of speed within half a
// window. Pure: every rank feeds it the same agreed durations and so decides the same.
#include <algorithm>
#include <cstddef>
#include <deque>
#include <vector>

namespace relt {

class Pace {
 public:
  static constexpr size_t kWindow = 31;  // durations kept (odd: one median)

  // `count` more passes or rounds took `seconds` together (count > 1: each the mean).
  void add(double seconds, size_t count = 1) {
    if (count == 0 || !(seconds >= 0.0)) return;
    for (size_t i = 0; i < std::min(count, kWindow); ++i) recent_.push_back(seconds / double(count));
    while (recent_.size() > kWindow) recent_.pop_front();
  }
  // The expected duration of the next one: the median of those kept (0 before any).
  double typical() const {
    if (recent_.empty()) return 0.0;
    std::vector<double> sorted(recent_.begin(), recent_.end());
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
    return sorted[sorted.size() / 2];
  }
  bool empty() const { return recent_.empty(); }

 private:
  std::deque<double> recent_;
};

}  // namespace relt
