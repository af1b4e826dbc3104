#pragma once
// Film positions of camera samples, kept on the pixel they were drawn for. In float, x + offset
// rounds up to x + 1 for an offset above 1 - 2^-16 at x = 365 (a dozen samples of a 1024 x 768
// pass): such a sample would land in the next pixel, or in the next row, which may be another
// rank's or not yet rendered. (A product u x width with u < 1 stays below width: no clamp there.)
#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace relt {

// Pixel coordinate `pixel` plus `offset` in [0, 1), below pixel + 1.
inline float inPixel(int pixel, float offset) {
  const float p = static_cast<float>(pixel);
  return std::min(p + offset, std::nextafter(p + 1.0f, p));
}

// The position at `offset` in [0, 1)^2 of pixel (x, y).
inline Vec2 positionInPixel(int x, int y, const Vec2& offset) { return Vec2(inPixel(x, offset.x), inPixel(y, offset.y)); }

}  // namespace relt
