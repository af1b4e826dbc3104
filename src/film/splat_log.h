#pragma once
// Splats kept in the order they were made, to be added to a film later: worker threads that step
// chains in whatever order they finish leave the film's sums bit for bit as one thread stepping
// them in turn would, when each chain's log is added in chain order.
#include <vector>

#include "film/film.h"

namespace relt {

class SplatLog {
 public:
  void addSplat(const Vec2& film, const Color& value, double weight) { splats_.push_back({film, value, weight}); }
  // Adds every splat to `film` in the order made (Film::addSplat, as if made there).
  void replayInto(Film& film) const {
    for (const Entry& e : splats_) film.addSplat(e.film, e.value, e.weight);
  }
  void clear() { splats_.clear(); }
  size_t size() const { return splats_.size(); }

 private:
  struct Entry {
    Vec2 film;
    Color value;
    double weight;
  };
  std::vector<Entry> splats_;
};

}  // namespace relt
