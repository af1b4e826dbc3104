#pragma once
// A vertex of a camera or light subpath, with the densities BDPT's MIS needs (Veach 1997 ch. 10).
#include <limits>

#include "light/lights.h"
#include "material/bsdf.h"

namespace relt {

struct PathVertex {
  enum class Type : uint8_t { Camera, Light, Surface };
  Type type = Type::Surface;
  // Surface: the BSDF is a Dirac delta. Light: the position is (punctual light). Camera: false.
  bool delta = false;
  SurfacePoint sp;
  // Surfaces: unit directions towards the previous vertex of its own subpath. wo is the traced
  // ray's (reversed), with which the BSDF is sampled and evaluated, as the path tracer does; toPrev
  // joins the stored positions, with which the MIS densities are evaluated. They differ by the ray
  // origin's offset, which is not small beside gaps of a millimetre (docs/ARCHITECTURE.md).
  Vec3 wo{0.0f};
  Vec3 toPrev{0.0f};
  Color beta{1.0f};  // subpath throughput up to this vertex (Veach's alpha)
  // Area densities of generating this vertex from its own subpath (fwd) and from the other end
  // (rev). Zero where the generating step was a delta scattering; the MIS walk treats 0 as 1.
  float pdfFwd = 0.0f, pdfRev = 0.0f;
  uint32_t light = std::numeric_limits<uint32_t>::max();  // Light vertices: index into LightSampler
  std::optional<Bsdf> bsdf;  // Surface vertices

  bool isSurface() const { return type == Type::Surface; }
  // Normal for geometry terms: surfaces and area lights have one, the pinhole and point lights not.
  bool hasNormal() const { return type == Type::Surface || (type == Type::Light && !delta); }
};

// Probability of continuing a subpath from a surface vertex. It depends only on the material, so
// the same value holds in both directions and the MIS densities stay exact (unlike throughput
// based roulette, whose reverse probabilities are unknown).
inline float continuationProbability(const Material& m) {
  if (m.kind == MaterialKind::Dielectric) return 1.0f;
  return std::clamp(maxComponent(m.baseColor), 0.0f, 1.0f);
}

// Veach 1997 §5.3: with shading normals the adjoint BSDF needs this factor on light subpaths.
inline float shadingCorrection(const SurfacePoint& sp, const Vec3& wo, const Vec3& wi) {
  const float den = std::abs(glm::dot(wo, sp.ng)) * std::abs(glm::dot(wi, sp.ns));
  return den > 0.0f ? std::abs(glm::dot(wo, sp.ns)) * std::abs(glm::dot(wi, sp.ng)) / den : 0.0f;
}

// Solid angle density at `from` towards `to` -> area density at `to`.
inline float solidAngleToArea(float pdfW, const PathVertex& from, const PathVertex& to) {
  const Vec3 d = to.sp.p - from.sp.p;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0f)) return 0.0f;
  float pdf = pdfW / dist2;
  if (to.hasNormal()) pdf *= std::abs(glm::dot(to.sp.ng, d)) / std::sqrt(dist2);
  return pdf;
}

}  // namespace relt
