#pragma once
// Kelemen et al. 2002 mutations of one primary-sample coordinate (thesis digest §2.8).
#include <cmath>

namespace relt {

// Small-step sizes: the step is log-uniform in (s1, s2].
struct KelemenSizes {
  float s1 = 1.0f / 1024.0f;
  float s2 = 1.0f / 64.0f;
};

// Moves u by +-dv with dv = s2 exp(-ln(s2 / s1) xi'), the sign and xi' taken from one uniform xi
// (xi < 1/2: +, xi' = 2 xi; else -, xi' = 2 xi - 1), wrapped into [0, 1). Symmetric in u -> u'.
inline float kelemenSmallStep(float u, float xi, const KelemenSizes& sizes) {
  const bool up = xi < 0.5f;
  const float x = up ? 2.0f * xi : 2.0f * xi - 1.0f;
  const float dv = sizes.s2 * std::exp(-std::log(sizes.s2 / sizes.s1) * x);
  float v = up ? u + dv : u - dv;
  if (v >= 1.0f) v -= 1.0f;
  if (v < 0.0f) v += 1.0f;
  // u - dv can round to exactly 1 after the wrap (u tiny); keep the half-open interval.
  return v < 1.0f ? v : 0.0f;
}

}  // namespace relt
