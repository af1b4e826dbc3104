#include "film/film.h"

namespace relt {

void Film::addSplat(const Vec2& film, const Color& value, double weight) {
  const int x = static_cast<int>(film.x), y = static_cast<int>(film.y);
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  double* px = &rgb_[3 * (static_cast<size_t>(y) * width_ + x)];
  px[0] += weight * value.x;
  px[1] += weight * value.y;
  px[2] += weight * value.z;
}

bool Film::addSample(const PathSample& sample, double weight) {
  if (!sample.finite()) {
    ++dropped_;
    return false;
  }
  for (const Splat& s : sample.splats) addSplat(s.film, s.value, weight);
  return true;
}

}  // namespace relt
