#pragma once
// Splats kept in the order they were made, to be added to a film later: worker threads that step
// chains in whatever order they finish leave the film's sums bit for bit as one thread stepping
// them in turn would, when each chain's log is added in chain order.
#include <cstdint>
#include <vector>

#include "film/film.h"

namespace relt {

class alignas(64) SplatLog {  // aligned: neighbouring chains' logs are written by different workers
 public:
  void addSplat(const Vec2& film, const Color& value, double weight) { splats_.push_back({film, value, weight}); }
  // As Film::addSample: a sample with a non-finite value or weight is dropped whole and counted.
  bool addSample(const PathSample& sample, double weight = 1.0) {
    if (addFiniteSample(*this, sample, weight)) return true;
    ++dropped_;
    return false;
  }
  // Adds every splat to `film` in the order made, and the dropped samples to its count: the film
  // ends as if they had been made there.
  void replayInto(Film& film) const {
    for (const Entry& e : splats_) film.addSplat(e.film, e.value, e.weight);
    film.addDropped(dropped_);
  }
  void clear() {
    splats_.clear();
    dropped_ = 0;
  }

 private:
  struct Entry {
    Vec2 film;
    Color value;
    double weight;
  };
  std::vector<Entry> splats_;
  uint64_t dropped_ = 0;
};

}  // namespace relt
