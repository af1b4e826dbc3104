#include "material/microfacet.h"

namespace relt {

float erfInv(float x) {
  // Giles 2010: two polynomial fits in w = -log(1 - x^2), central and tail.
  float w = -std::log((1.0f - x) * (1.0f + x));
  float p;
  if (w < 5.0f) {
    w -= 2.5f;
    p = 2.81022636e-08f;
    p = 3.43273939e-07f + p * w;
    p = -3.5233877e-06f + p * w;
    p = -4.39150654e-06f + p * w;
    p = 0.00021858087f + p * w;
    p = -0.00125372503f + p * w;
    p = -0.00417768164f + p * w;
    p = 0.246640727f + p * w;
    p = 1.50140941f + p * w;
  } else {
    w = std::sqrt(w) - 3.0f;
    p = -0.000200214257f;
    p = 0.000100950558f + p * w;
    p = 0.00134934322f + p * w;
    p = -0.00367342844f + p * w;
    p = 0.00573950773f + p * w;
    p = -0.0076224613f + p * w;
    p = 0.00943887047f + p * w;
    p = 1.00167406f + p * w;
    p = 2.83297682f + p * w;
  }
  return p * x;
}

namespace {

constexpr float kInvSqrtPi = 0.56418958354775628f;

// Heitz 2018, "Sampling the GGX distribution of visible normals" (JCGT 7(4)): stretch the view to
// the alpha = 1 configuration, where visible normals are uniform on the projected hemisphere; sample
// a disk warped towards the visible half; lift onto the hemisphere and unstretch.
Vec3 sampleVisibleGgx(const Vec3& w, float alpha, const Vec2& u) {
  const Vec3 v = glm::normalize(Vec3(alpha * w.x, alpha * w.y, w.z));
  const float len2 = v.x * v.x + v.y * v.y;
  const Vec3 t1 = len2 > 0.0f ? Vec3(-v.y, v.x, 0.0f) / std::sqrt(len2) : Vec3(1.0f, 0.0f, 0.0f);
  const Vec3 t2 = glm::cross(v, t1);
  const float r = std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  const float p1 = r * std::cos(phi);
  float p2 = r * std::sin(phi);
  // Heitz 2018 Listing 1: the half disk hidden by the view is folded onto the visible half.
  const float s = 0.5f * (1.0f + v.z);
  p2 = (1.0f - s) * safeSqrt(1.0f - p1 * p1) + s * p2;
  const Vec3 nh = p1 * t1 + p2 * t2 + safeSqrt(1.0f - p1 * p1 - p2 * p2) * v;
  const Vec3 m(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z));
  const float len = glm::length(m);
  return len > 0.0f ? m / len : Vec3(0.0f, 0.0f, 1.0f);
}

// Slope x~ of a visible microfacet for the alpha = 1 Beckmann surface seen from polar angle theta
// in the x-z plane. Its density is proportional to exp(-x^2) (1 - x tan theta) on x < cot theta
// (projected area times slope density, Heitz & d'Eon 2014 Sec. 4), so with b = erf(x) the CDF is
//   C(b) = (1 + b + tan theta exp(-x^2) / sqrt(pi)) / (1 + erf(cot theta) + tan theta exp(-cot^2) / sqrt(pi))
// and dC/db = (1 - x tan theta) / normaliser. We invert C by Newton's method in b, safeguarded by
// bisection (Jakob 2014 does the same; the b-parameterisation keeps the derivative bounded).
float sampleVisibleSlopeBeckmann(float theta, float tanTheta, float u) {
  u = std::clamp(u, 1e-6f, 1.0f - 1e-6f);  // erfInv(+-1) is infinite
  const float cotTheta = 1.0f / tanTheta;  // +inf at normal incidence: erf -> 1, exp -> 0
  float lo = -1.0f, hi = std::erf(cotTheta);
  const float norm = 1.0f / (1.0f + hi + kInvSqrtPi * tanTheta * std::exp(-cotTheta * cotTheta));
  // Initial guess b = hi - (1 + hi)(1 - u)^k(theta): exact at normal incidence (k = 1, C linear in
  // b); k is our least-squares fit of C over theta in [0, pi/2]. It saves about two iterations.
  const float k = 1.0f + theta * (-0.839f + 0.3016f * theta);
  float b = hi - (1.0f + hi) * std::pow(1.0f - u, k);
  for (int it = 0; it < 20; ++it) {
    if (!(b > lo && b < hi)) b = 0.5f * (lo + hi);  // also catches NaN
    const float x = erfInv(b);
    const float c = norm * (1.0f + b + kInvSqrtPi * tanTheta * std::exp(-x * x)) - u;
    if (std::abs(c) < 1e-6f) break;
    if (c > 0.0f)
      hi = b;
    else
      lo = b;
    b -= c / (norm * (1.0f - x * tanTheta));
  }
  return erfInv(std::clamp(b, -1.0f + 1e-7f, 1.0f - 1e-7f));
}

// Heitz & d'Eon 2014 Sec. 4: stretch to alpha = 1, sample the visible slopes for the stretched polar
// angle, rotate to the view's azimuth, unstretch and convert the slope to a normal.
Vec3 sampleVisibleBeckmann(const Vec3& w, float alpha, const Vec2& u) {
  const Vec3 v = glm::normalize(Vec3(alpha * w.x, alpha * w.y, w.z));
  const float sinTheta = std::sqrt(v.x * v.x + v.y * v.y);
  float cosPhi = 1.0f, sinPhi = 0.0f;
  if (sinTheta > 0.0f) {
    cosPhi = v.x / sinTheta;
    sinPhi = v.y / sinTheta;
  }
  const float x = sampleVisibleSlopeBeckmann(std::atan2(sinTheta, v.z), sinTheta / v.z, u.x);
  // The slope across the view plane is independent of the view: a Gaussian, erf^-1 of a uniform.
  const float y = erfInv(std::clamp(2.0f * u.y - 1.0f, -1.0f + 1e-6f, 1.0f - 1e-6f));
  const float sx = alpha * (cosPhi * x - sinPhi * y);
  const float sy = alpha * (sinPhi * x + cosPhi * y);
  return glm::normalize(Vec3(-sx, -sy, 1.0f));
}

}  // namespace

Vec3 MicrofacetDistribution::sampleVisible(const Vec3& w, const Vec2& u) const {
  return type_ == Microfacet::GGX ? sampleVisibleGgx(w, alpha_, u) : sampleVisibleBeckmann(w, alpha_, u);
}

}  // namespace relt
