#pragma once
// Accumulation buffer for splats (double precision, box filter of one pixel).
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"
#include "path/splat.h"

namespace relt {

// Adds a sample's splats scaled by `weight` to `sink` (a Film, a SplatLog), unless a value or the
// weight is not finite: then nothing, and false (the sink counts it as dropped).
template <class Sink>
bool addFiniteSample(Sink& sink, const PathSample& sample, double weight) {
  if (!sample.finite() || !std::isfinite(weight)) return false;
  for (const Splat& s : sample.splats) sink.addSplat(s.film, s.value, weight);
  return true;
}

class Film {
 public:
  Film(int width, int height) : width_(width), height_(height), rgb_(size_t(3) * width * height, 0.0) {}

  int width() const { return width_; }
  int height() const { return height_; }

  // Adds every splat of a sample scaled by `weight`. A sample with any NaN or infinite value, or
  // a weight that is not finite, is dropped whole and counted: one bad number must not poison a pixel.
  bool addSample(const PathSample& sample, double weight = 1.0);
  void addSplat(const Vec2& film, const Color& value, double weight);
  // Samples dropped elsewhere (a SplatLog's), counted here.
  void addDropped(uint64_t samples) { dropped_ += samples; }
  // Adds weight x another film's sums (same size) and its dropped-sample count.
  void addWeighted(const Film& other, double weight);
  // Zero sums and no dropped samples, as new.
  void clear();

  // Raw sums (r, g, b per pixel, row-major from the top), reduced across ranks by the MPI layer.
  std::vector<double>& data() { return rgb_; }
  const std::vector<double>& data() const { return rgb_; }
  uint64_t droppedSamples() const { return dropped_; }

 private:
  int width_, height_;
  std::vector<double> rgb_;
  uint64_t dropped_ = 0;
};

// Adds each of a worker's films into the matching one of `into` (the same count and sizes) and
// clears the worker's: a rank's workers splat apart and are gathered before the sums are read.
void gatherWorkerFilms(std::span<Film> into, std::span<Film> worker);
// The same for per-pixel tallies kept beside a film.
void gatherWorkerTally(std::vector<double>& into, std::vector<double>& worker);

}  // namespace relt
