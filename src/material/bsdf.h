#pragma once
// BSDFs evaluated at a surface point. Directions are world-space unit vectors pointing away from
// the surface: wo towards where light goes (the previous vertex on a camera path), wi towards where
// it comes from. Values exclude the cosine factor.
#include <optional>

#include "core/math.h"
#include "material/material.h"

namespace relt {

// Radiance: camera subpaths (adjoint BSDF not needed). Importance: light subpaths; refraction
// then omits the 1/eta^2 radiance scaling (Veach 1997, 5.2), which makes dielectrics non-symmetric.
enum class TransportMode : uint8_t { Radiance, Importance };

// The lobe parameters actually used by a BSDF instance. Tempering (a later feature) replaces them:
// it multiplies alpha and treats smooth surfaces as Beckmann with a small alpha.
struct Roughness {
  float alpha = 0.0f;  // 0 = smooth (delta)
  Microfacet distribution = Microfacet::GGX;
};

struct BsdfSample {
  Vec3 wi;          // sampled direction (world)
  // BSDF value and solid-angle density, so that f |cos wi| / pdf is the throughput weight. For a
  // delta lobe, f is the delta's coefficient divided by |cos wi| and pdf is the discrete
  // probability of choosing that lobe (1 for a mirror; Fresnel R or T for smooth glass).
  Color f;
  float pdf = 0.0f;
  bool delta = false;
};

class Bsdf {
 public:
  // shadingN: interpolated shading normal; geometricN: true triangle normal. Both unit length,
  // any orientation (the BSDF works out which side it is on).
  Bsdf(const Material& material, const Vec3& shadingN, const Vec3& geometricN);
  Bsdf(const Material& material, const Vec3& shadingN, const Vec3& geometricN, Roughness override);

  // True when every lobe is a Dirac delta (smooth mirror or glass): eval and pdf return zero.
  bool isDelta() const { return alpha_ == 0.0f && material_->kind != MaterialKind::Lambert; }
  Color eval(const Vec3& wo, const Vec3& wi, TransportMode mode) const;
  // Density of sampling wi given wo. The reverse density is pdf(wi, wo) (with the mode swapped
  // where relevant: the density itself does not depend on the mode).
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // eval and pdf in one pass (next-event estimation needs both).
  struct Value {
    Color f;
    float pdf;
  };
  // Lambert inline (next-event estimation calls this at every diffuse vertex).
  Value evaluate(const Vec3& wo, const Vec3& wi, TransportMode mode) const {
    if (material_->kind != MaterialKind::Lambert) return evaluateLobes(wo, wi, mode);
    return lambert(*material_, frame_, ng_, wo, wi);
  }
  // Lambert's value and density: reflection as judged by ng, with the shading frame agreeing; only
  // the normal components of wo and wi matter. evalLocal uses it too.
  static Value lambert(const Material& mat, const Frame& frame, const Vec3& ng, const Vec3& wo, const Vec3& wi) {
    const float go = glm::dot(wo, ng), gi = glm::dot(wi, ng);
    const float co = glm::dot(wo, frame.n), ci = glm::dot(wi, frame.n);
    if (go == 0.0f || gi == 0.0f || (go > 0.0f) != (gi > 0.0f) || co * ci <= 0.0f) return {Color(0.0f), 0.0f};
    return {mat.baseColor * kInvPi, std::abs(ci) * kInvPi};
  }
  // u: two numbers for the direction, uLobe: one for the lobe choice (reflect/refract).
  std::optional<BsdfSample> sample(const Vec3& wo, const Vec2& u, float uLobe, TransportMode mode) const;

  const Material& material() const { return *material_; }
  const Roughness& roughness() const { return rough_; }
  // Shading frame; its normal is the shading normal turned to the side ng points to (the outside).
  const Frame& frame() const { return frame_; }
  const Vec3& geometricNormal() const { return ng_; }

 private:
  Value evaluateLobes(const Vec3& wo, const Vec3& wi, TransportMode mode) const;
  // sample()'s outgoing direction: world and local, mirrored into the upper hemisphere (up),
  // which side of the shading normal it is on (side, +-1) and go = dot(world, ng).
  struct Outgoing {
    Vec3 world, local, up;
    float side, go;
  };
  // sample() per lobe (etaRel: eta on the far side over eta on wo's side).
  std::optional<BsdfSample> sampleLambert(const Vec3& woW, float go, const Vec2& u) const;
  std::optional<BsdfSample> sampleConductor(const Outgoing& out, const Vec2& u, TransportMode mode) const;
  std::optional<BsdfSample> sampleSmoothDielectric(const Outgoing& out, float etaRel, float uLobe,
                                                   TransportMode mode) const;
  std::optional<BsdfSample> sampleRoughDielectric(const Outgoing& out, float etaRel, const Vec2& u, float uLobe,
                                                  TransportMode mode) const;
  bool toWorldChecked(const Vec3& wi, bool sameSide, float go, Vec3* wiW) const;
  std::optional<BsdfSample> valuedSample(const Vec3& woW, const Vec3& wiW, TransportMode mode) const;

  const Material* material_;
  Frame frame_;
  Vec3 ng_;
  Roughness rough_;
  float alpha_ = 0.0f;  // alpha used by the lobes: 0 (delta) or rough_.alpha clamped to >= 1e-4
};

}  // namespace relt
