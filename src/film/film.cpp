#include "film/film.h"

#include <algorithm>
#include <cmath>

namespace relt {

void Film::addSplat(const Vec2& film, const Color& value, double weight) {
  // Box filter of one pixel: floor, not truncation, so (-1, 0) is off the film; NaN fails the test.
  const float fx = std::floor(film.x), fy = std::floor(film.y);
  if (!(fx >= 0.0f && fy >= 0.0f && fx < static_cast<float>(width_) && fy < static_cast<float>(height_))) return;
  const int x = static_cast<int>(fx), y = static_cast<int>(fy);
  double* px = &rgb_[3 * (static_cast<size_t>(y) * width_ + x)];
  px[0] += weight * value.x;
  px[1] += weight * value.y;
  px[2] += weight * value.z;
}

bool Film::addSample(const PathSample& sample, double weight) {
  if (addFiniteSample(*this, sample, weight)) return true;
  ++dropped_;
  return false;
}

void Film::addWeighted(const Film& other, double weight) {
  dropped_ += other.dropped_;
  if (weight == 0.0) return;
  for (size_t k = 0; k < rgb_.size() && k < other.rgb_.size(); ++k) rgb_[k] += weight * other.rgb_[k];
}

void Film::clear() {
  std::fill(rgb_.begin(), rgb_.end(), 0.0);
  dropped_ = 0;
}

void gatherWorkerFilms(std::span<Film> into, std::span<Film> worker) {
  for (size_t k = 0; k < worker.size(); ++k) {
    into[k].addWeighted(worker[k], 1.0);
    worker[k].clear();
  }
}

void gatherWorkerTally(std::vector<double>& into, std::vector<double>& worker) {
  for (size_t i = 0; i < worker.size(); ++i) into[i] += worker[i];
  std::fill(worker.begin(), worker.end(), 0.0);
}

}  // namespace relt
