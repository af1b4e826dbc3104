#pragma once
// Warps from the unit square to common domains, with their densities.
#include <algorithm>
#include <vector>

#include "core/math.h"

namespace relt {

// (cos x, sin x) for |x| <= pi/4 by Taylor polynomials: truncation below 3e-7, far cheaper than
// libm's sincosf, which the warps below call on every bounce.
inline Vec2 cosSinQuarterPi(float x) {
  const float x2 = x * x;
  const float c = 1.0f + x2 * (-1.0f / 2 + x2 * (1.0f / 24 + x2 * (-1.0f / 720 + x2 * (1.0f / 40320))));
  const float s = x * (1.0f + x2 * (-1.0f / 6 + x2 * (1.0f / 120 + x2 * (-1.0f / 5040))));
  return Vec2(c, s);
}

// Shirley-Chiu concentric map of the unit square onto the unit disk.
inline Vec2 concentricDisk(const Vec2& u) {
  const Vec2 o = 2.0f * u - Vec2(1.0f);
  if (o.x == 0.0f && o.y == 0.0f) return Vec2(0.0f);
  if (std::abs(o.x) > std::abs(o.y)) {
    const Vec2 cs = cosSinQuarterPi((kPi / 4.0f) * (o.y / o.x));  // theta in [-pi/4, pi/4]
    return o.x * cs;
  }
  // theta = pi/2 - phi with phi in [-pi/4, pi/4]: (cos theta, sin theta) = (sin phi, cos phi).
  const Vec2 cs = cosSinQuarterPi((kPi / 4.0f) * (o.x / o.y));
  return o.y * Vec2(cs.y, cs.x);
}

// Cosine-weighted direction around +z; density cos(theta) / pi.
inline Vec3 cosineHemisphere(const Vec2& u) {
  const Vec2 d = concentricDisk(u);
  return Vec3(d.x, d.y, safeSqrt(1.0f - d.x * d.x - d.y * d.y));
}
inline float cosineHemispherePdf(float cosTheta) { return std::max(cosTheta, 0.0f) * kInvPi; }

inline Vec3 uniformSphere(const Vec2& u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = safeSqrt(1.0f - z * z);
  const float phi = 2.0f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// Direction inside a cone of half-angle acos(cosMax) around +z; density 1 / (2 pi (1 - cosMax)).
inline Vec3 uniformCone(const Vec2& u, float cosMax) {
  const float cosT = (1.0f - u.x) + u.x * cosMax;
  const float sinT = safeSqrt(1.0f - cosT * cosT);
  const float phi = 2.0f * kPi * u.y;
  return Vec3(std::cos(phi) * sinT, std::sin(phi) * sinT, cosT);
}

// Barycentric coordinates (b1, b2) uniformly distributed over a triangle (Heitz 2019, low distortion).
inline Vec2 uniformTriangle(const Vec2& u) {
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2.0f;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2.0f;
    b0 = u.x - b1;
  }
  return Vec2(b0, b1);
}

// A discrete distribution sampled by inverting its CDF.
class Distribution1D {
 public:
  Distribution1D() = default;
  explicit Distribution1D(const std::vector<double>& weights);
  size_t size() const { return pmf_.size(); }
  bool empty() const { return pmf_.empty(); }
  double total() const { return total_; }
  float pmf(size_t i) const { return pmf_[i]; }
  // Returns an index and rescales u to a fresh uniform number in [0, 1) for reuse. Needs at least
  // one entry (the light sampler is never asked when the scene has no light).
  size_t sample(float u, float* uRemapped = nullptr) const {
    const double target = static_cast<double>(u) * total_;
    // First index whose upper CDF bound exceeds the target (std::upper_bound's answer), found
    // without data-dependent branches: light picks land on random entries, and mispredicted
    // search branches cost more than the comparisons.
    const double* base = cdf_.data() + 1;
    for (size_t n = cdf_.size() - 1; n > 1;) {
      const size_t half = n / 2;
      base += base[half] <= target ? half : 0;
      n -= half;
    }
    base += *base <= target ? 1 : 0;
    size_t i = std::min(static_cast<size_t>(base - cdf_.data() - 1), pmf_.size() - 1);
    while (pmf_[i] == 0.0f && i > 0) --i;  // only when every weight is zero: answer the first entry
    if (uRemapped) *uRemapped = remap(target, i);
    return i;
  }

 private:
  float remap(double target, size_t i) const;

  std::vector<float> pmf_;
  std::vector<double> cdf_;
  double total_ = 0.0;
};

}  // namespace relt
