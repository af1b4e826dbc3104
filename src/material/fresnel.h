#pragma once
// Fresnel reflectance: exact for dielectrics, Schlick's approximation for conductors.
#include "core/math.h"

namespace relt {

// Unpolarised Fresnel reflectance of a smooth dielectric interface (Born & Wolf; Walter et al. 2007
// Eq. 22 in its exact form). cosI is the cosine between the incident direction and the normal that
// points to the OUTSIDE medium; a negative cosI means incidence from inside. eta = eta_inside /
// eta_outside. Returns 1 under total internal reflection.
inline float fresnelDielectric(float cosI, float eta) {
  if (cosI < 0.0f) {
    eta = 1.0f / eta;
    cosI = -cosI;
  }
  cosI = std::min(cosI, 1.0f);
  const float sin2T = (1.0f - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0f) return 1.0f;
  const float cosT = std::sqrt(1.0f - sin2T);
  const float rParallel = (eta * cosI - cosT) / (eta * cosI + cosT);
  const float rPerpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

// Schlick 1994: F0 + (1 - F0)(1 - cos)^5, with F0 the reflectance at normal incidence (the glTF
// metallic baseColor). cosI is clamped to [0, 1].
inline Color fresnelSchlick(const Color& f0, float cosI) {
  const float m = 1.0f - std::clamp(cosI, 0.0f, 1.0f);
  const float m2 = m * m;
  return f0 + (Color(1.0f) - f0) * (m2 * m2 * m);
}

}  // namespace relt
