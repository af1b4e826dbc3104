#pragma once
// Warps from the unit square to common domains, with their densities.
#include <vector>

#include "core/math.h"

namespace relt {

inline Vec2 concentricDisk(const Vec2& u) {
  const Vec2 o = 2.0f * u - Vec2(1.0f);
  if (o.x == 0.0f && o.y == 0.0f) return Vec2(0.0f);
  float r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = (kPi / 4.0f) * (o.y / o.x);
  } else {
    r = o.y;
    theta = (kPi / 2.0f) - (kPi / 4.0f) * (o.x / o.y);
  }
  return r * Vec2(std::cos(theta), std::sin(theta));
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

// MIS heuristics on (weighted) densities.
inline float powerHeuristic(float f, float g) {
  const float f2 = f * f;
  return f2 == 0.0f ? 0.0f : f2 / (f2 + g * g);
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
  // Returns an index and rescales u to a fresh uniform number in [0, 1) for reuse.
  size_t sample(float u, float* uRemapped = nullptr) const;

 private:
  std::vector<float> pmf_;
  std::vector<double> cdf_;
  double total_ = 0.0;
};

}  // namespace relt
