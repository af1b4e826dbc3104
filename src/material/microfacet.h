#pragma once
// Isotropic microfacet distributions (GGX and Beckmann) in a local frame whose z axis is the
// macro-surface normal. All directions are unit vectors. Conventions follow Walter et al. 2007
// ("Microfacet models for refraction through rough surfaces") and Heitz 2014 ("Understanding the
// masking-shadowing function in microfacet-based BRDFs").
//
// Shadowing-masking: height-correlated Smith, G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014
// Eq. 99). We use the same closed form for transmission, as pbrt-v4 does; the exact height-correlated
// transmission term is a Beta function (Heitz 2014 Sec. 6.3) that is costly and differs little.
//
// Sampling: distribution of visible normals D_w(m) = G1(w) max(0, w.m) D(m) / w.z for both
// distributions: GGX with Heitz 2018 ("Sampling the GGX distribution of visible normals"), Beckmann
// by numerically inverting the visible-slope CDF (Jakob 2014, "An improved visible normal sampling
// routine for the Beckmann distribution"), on top of Heitz & d'Eon 2014's stretch/rotate scheme.
#include "core/math.h"
#include "material/material.h"

namespace relt {

class MicrofacetDistribution {
 public:
  MicrofacetDistribution(Microfacet type, float alpha) : type_(type), alpha_(alpha), alpha2_(alpha * alpha) {}

  Microfacet type() const { return type_; }
  float alpha() const { return alpha_; }

  // Normal distribution D(m), normalised so that the integral of D(m) m.z over the hemisphere is 1.
  float D(const Vec3& m) const {
    const float cos2 = m.z * m.z;
    if (m.z <= 0.0f || cos2 == 0.0f) return 0.0f;
    const float sin2 = m.x * m.x + m.y * m.y;  // direct, not 1 - cos2: exact near the pole
    if (type_ == Microfacet::GGX) {
      // Walter et al. 2007 Eq. 33, rewritten as a^2 / (pi (a^2 cos^2 + sin^2)^2) so that tiny alpha
      // (1e-4 for tempered specular surfaces) does not lose all precision.
      const float d = alpha2_ * cos2 + sin2;
      return alpha2_ / (kPi * d * d);
    }
    // Beckmann D (Walter et al. 2007 Sec. 5.1): exp(-tan^2 / a^2) / (pi a^2 cos^4).
    const float e = std::exp(-sin2 / (cos2 * alpha2_));
    if (e == 0.0f) return 0.0f;  // avoids 0 / 0 when cos^4 underflows
    return e / (kPi * alpha2_ * cos2 * cos2);
  }

  // Smith Lambda(w); depends on |w.z| only, so it serves both sides of the surface.
  float lambda(const Vec3& w) const {
    const float cos2 = w.z * w.z;
    const float sin2 = w.x * w.x + w.y * w.y;
    if (sin2 == 0.0f) return 0.0f;
    if (cos2 == 0.0f) return INFINITY;
    if (type_ == Microfacet::GGX) {
      // GGX Lambda (Heitz 2014 Sec. 5.3): (-1 + sqrt(1 + a^2 tan^2)) / 2, with the cancellation-free form
      // sqrt(1 + x) - 1 = x / (sqrt(1 + x) + 1).
      const float x = alpha2_ * sin2 / cos2;
      return 0.5f * x / (std::sqrt(1.0f + x) + 1.0f);
    }
    // Exact Beckmann Lambda (Heitz 2014 Sec. 5.3): (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),
    // a = 1 / (alpha tan theta), written with erfc to avoid
    // cancelling erf(a) - 1. Beyond a = 5 Lambda is below 1e-13: zero for our purpose.
    const float a = std::sqrt(cos2 / (alpha2_ * sin2));
    if (a >= 5.0f) return 0.0f;
    constexpr float kInvSqrtPi = 0.56418958354775628f;
    return std::max(0.0f, 0.5f * (std::exp(-a * a) * kInvSqrtPi / a - std::erfc(a)));
  }

  float G1(const Vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
  // Height-correlated Smith shadowing-masking (Heitz 2014 Eq. 99).
  float G2(const Vec3& wo, const Vec3& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

  // Samples a microfacet normal m (m.z > 0) from the visible-normal distribution D_w; requires w.z > 0.
  Vec3 sampleVisible(const Vec3& w, const Vec2& u) const;
  // Density of sampleVisible: D_w(m) = G1(w) max(0, w.m) D(m) / w.z (Heitz & d'Eon 2014, Sec. 3).
  float pdfVisible(const Vec3& w, const Vec3& m) const {
    const float wm = glm::dot(w, m);
    if (w.z <= 0.0f || wm <= 0.0f) return 0.0f;
    return G1(w) * wm * D(m) / w.z;
  }

 private:
  Microfacet type_;
  float alpha_, alpha2_;
};

// Inverse error function (Giles 2010, "Approximating the erfinv function", single-precision
// polynomials; relative error about 1e-7). Defined on (-1, 1); returns +-inf at +-1.
float erfInv(float x);

}  // namespace relt
