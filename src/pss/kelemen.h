#pragma once
// Kelemen et al. 2002 mutations of one primary-sample coordinate (thesis digest §2.8).
#include <bit>
#include <cmath>
#include <cstdint>

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

namespace relt {

// 2^e for -126 < e <= 0: exponent bits plus a degree-6 Taylor polynomial of 2^f on [0, 1)
// (relative error below 2e-5, far finer than the kernel needs; libm's expf dominated chain time).
inline float exp2NonPositive(float e) {
  const float fl = std::floor(e);
  const float f = e - fl;
  const float p =
      1.0f + f * (0.693147181f + f * (0.240226507f + f * (0.0555041087f + f * (0.00961812911f +
                                                                              f * (0.00133335581f + f * 0.000154035304f)))));
  const uint32_t bits = static_cast<uint32_t>(static_cast<int32_t>(fl) + 127) << 23;
  return p * std::bit_cast<float>(bits);
}

// The same small step with its constants worked out once (what the chains call per coordinate).
class KelemenStep {
 public:
  explicit KelemenStep(const KelemenSizes& sizes)
      : s2_(sizes.s2), scale_(-std::log2(sizes.s2 / sizes.s1)) {
    // E[dv^2] of the log-uniform size: s2^2 (1 - (s1/s2)^2) / (2 ln(s2/s1)).
    const double l = std::log(double(sizes.s2) / sizes.s1), r = double(sizes.s1) / sizes.s2;
    sigma_ = static_cast<float>(sizes.s2 * std::sqrt((1.0 - r * r) / (2.0 * l)));
  }
  // Standard deviation of one step's displacement.
  float sigma() const { return sigma_; }
  float operator()(float u, float xi) const {
    const bool up = xi < 0.5f;
    const float x = up ? 2.0f * xi : 2.0f * xi - 1.0f;
    const float dv = s2_ * exp2NonPositive(scale_ * x);
    float v = up ? u + dv : u - dv;
    if (v >= 1.0f) v -= 1.0f;
    if (v < 0.0f) v += 1.0f;
    return v < 1.0f ? v : 0.0f;
  }

 private:
  float s2_, scale_, sigma_ = 0.0f;
};

// Adds a displacement d (any size) to u and wraps into [0, 1).
inline float wrapUnit(float u, float d) {
  float v = u + d;
  v -= std::floor(v);
  return v < 1.0f ? v : 0.0f;
}

}  // namespace relt
