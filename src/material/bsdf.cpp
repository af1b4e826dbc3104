#include "material/bsdf.h"

#include "core/sampling.h"
#include "material/fresnel.h"
#include "material/microfacet.h"

// Local frames. Every lobe works in the shading frame, whose normal has been turned to the side the
// geometric normal ng points to. Opaque lobes further mirror z so that wo.z > 0 (two-sided
// materials); dielectrics keep +z = outside (ior 1) and -z = inside (material ior).
//
// Notation for refraction: eta_o, eta_i are the indices on the sides of wo and wi. The
// Importance-mode BTDF is the adjoint of the Radiance-mode one: f_imp(wo, wi) = f_rad(wi, wo), and
// f_rad(wo, wi) = f_imp(wo, wi) (eta_o / eta_i)^2 (Veach 1997 Sec. 5.2).

namespace relt {
namespace {

constexpr float kMinAlpha = 1e-4f;

struct LobeValue {
  Color f{0.0f};
  float pdf = 0.0f;
};

bool onPositiveSide(float x) { return x > 0.0f; }

LobeValue finiteOrZero(const LobeValue& v) {
  if (!(v.pdf > 0.0f) || !std::isfinite(v.pdf) || !isFinite(v.f)) return {};
  return v;
}

// Rough conductor in the mirrored frame (wo.z > 0). Walter et al. 2007 Eq. 20 with the
// height-correlated G2; density = visible-normal density times the reflection Jacobian
// 1 / (4 wo.m) (Walter Eq. 14): G1(wo) D(m) / (4 wo.z).
LobeValue roughConductor(const Color& f0, const MicrofacetDistribution& dist, const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return {};
  const Vec3 h = wo + wi;
  const float len2 = glm::dot(h, h);
  if (len2 == 0.0f) return {};
  const Vec3 m = h / std::sqrt(len2);
  const float cosOm = glm::dot(wo, m);  // equals wi.m for a reflection half vector
  const float d = dist.D(m);
  if (cosOm <= 0.0f || d == 0.0f) return {};
  const float lambdaO = dist.lambda(wo), lambdaI = dist.lambda(wi);
  LobeValue v;
  v.f = fresnelSchlick(f0, cosOm) * (d / (4.0f * wo.z * wi.z * (1.0f + lambdaO + lambdaI)));
  v.pdf = d / (4.0f * wo.z * (1.0f + lambdaO));
  return finiteOrZero(v);
}

// Rough dielectric, +z outside. Walter et al. 2007 with visible-normal sampling: the lobe is chosen
// with probability F(wo.m) for reflection, 1 - F for refraction.
LobeValue roughDielectric(const Material& mat, const MicrofacetDistribution& dist, const Vec3& wo, const Vec3& wi,
                          TransportMode mode) {
  if (wo.z == 0.0f || wi.z == 0.0f) return {};
  const bool reflect = (wo.z > 0.0f) == (wi.z > 0.0f);
  const float etaO = wo.z > 0.0f ? 1.0f : mat.ior;
  const float etaI = wi.z > 0.0f ? 1.0f : mat.ior;
  // Half vectors: Walter Eq. 13 (reflection) and the generalised one of Eq. 16 (refraction).
  Vec3 h = reflect ? wo + wi : etaO * wo + etaI * wi;
  const float len2 = glm::dot(h, h);
  if (len2 == 0.0f) return {};
  h /= std::sqrt(len2);
  const Vec3 m = h.z < 0.0f ? -h : h;
  const float cosOm = glm::dot(wo, m), cosIm = glm::dot(wi, m);
  // The microfacet must face each direction from that direction's side (the chi+ factors of G2).
  if (cosOm * wo.z <= 0.0f || cosIm * wi.z <= 0.0f) return {};
  const float d = dist.D(m);
  if (d == 0.0f) return {};
  // For refraction, take the cosine on the outside: F is the same from either side, and this form is
  // well conditioned near the critical angle, which keeps f reciprocal in floating point.
  const float fresnel = fresnelDielectric(reflect || wo.z > 0.0f ? cosOm : cosIm, mat.ior);
  const float lambdaO = dist.lambda(wo), lambdaI = dist.lambda(wi);
  const float g2 = 1.0f / (1.0f + lambdaO + lambdaI);
  // Visible-normal density of m seen from wo (Heitz & d'Eon 2014): G1(wo) |wo.m| D(m) / |wo.z|.
  const float pdfM = d * std::abs(cosOm) / ((1.0f + lambdaO) * std::abs(wo.z));
  LobeValue v;
  if (reflect) {
    v.f = Color(fresnel * d * g2 / (4.0f * std::abs(wo.z * wi.z)));  // Walter Eq. 20
    v.pdf = fresnel * pdfM / (4.0f * std::abs(cosOm));               // Walter Eq. 14
  } else {
    const float denom = etaO * cosOm + etaI * cosIm;
    if (denom == 0.0f) return {};
    const float invDenom2 = 1.0f / (denom * denom);
    // Walter Eq. 21 carries eta_o^2 for radiance (wo is where light goes); its adjoint eta_i^2.
    const float etaScale = mode == TransportMode::Radiance ? etaO * etaO : etaI * etaI;
    const float t = 1.0f - fresnel;
    v.f = mat.baseColor * (t * d * g2 * std::abs(cosOm * cosIm) * etaScale * invDenom2 / std::abs(wo.z * wi.z));
    v.pdf = t * pdfM * etaI * etaI * std::abs(cosIm) * invDenom2;  // Walter Eq. 17 Jacobian
  }
  return finiteOrZero(v);
}

// Shared by eval and pdf (and by sample, so that all three agree exactly).
LobeValue evalLocal(const Material& mat, const Frame& frame, const Vec3& ng, float alpha, Microfacet type,
                    const Vec3& woW, const Vec3& wiW, TransportMode mode) {
  if (mat.kind == MaterialKind::Lambert) {
    const Bsdf::Value v = Bsdf::lambert(mat, frame, ng, woW, wiW);
    return {v.f, v.pdf};
  }
  const float go = glm::dot(woW, ng), gi = glm::dot(wiW, ng);
  if (go == 0.0f || gi == 0.0f) return {};
  Vec3 wo = frame.toLocal(woW), wi = frame.toLocal(wiW);
  if (mat.kind == MaterialKind::Dielectric) {
    // Both directions must be on the same side in the shading frame as geometrically: the side
    // decides the medium, hence eta.
    if (alpha == 0.0f || wo.z * go <= 0.0f || wi.z * gi <= 0.0f) return {};
    return roughDielectric(mat, MicrofacetDistribution(type, alpha), wo, wi, mode);
  }
  // Opaque: reflection only, as judged by ng, and the shading frame must agree.
  if (onPositiveSide(go) != onPositiveSide(gi) || wo.z * wi.z <= 0.0f) return {};
  if (wo.z < 0.0f) {
    wo.z = -wo.z;
    wi.z = -wi.z;
  }
  if (alpha == 0.0f) return {};
  return roughConductor(mat.baseColor, MicrofacetDistribution(type, alpha), wo, wi);
}

}  // namespace

Bsdf::Bsdf(const Material& material, const Vec3& shadingN, const Vec3& geometricN)
    : Bsdf(material, shadingN, geometricN, Roughness{material.alpha, material.distribution}) {}

Bsdf::Bsdf(const Material& material, const Vec3& shadingN, const Vec3& geometricN, Roughness override)
    : material_(&material),
      frame_(glm::dot(shadingN, geometricN) < 0.0f ? -shadingN : shadingN),
      ng_(geometricN),
      rough_(override) {
  alpha_ = rough_.alpha > 0.0f ? std::max(rough_.alpha, kMinAlpha) : 0.0f;
}

Color Bsdf::eval(const Vec3& wo, const Vec3& wi, TransportMode mode) const {
  return evalLocal(*material_, frame_, ng_, alpha_, rough_.distribution, wo, wi, mode).f;
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  return evalLocal(*material_, frame_, ng_, alpha_, rough_.distribution, wo, wi, TransportMode::Radiance).pdf;
}

Bsdf::Value Bsdf::evaluateLobes(const Vec3& wo, const Vec3& wi, TransportMode mode) const {
  const LobeValue v = evalLocal(*material_, frame_, ng_, alpha_, rough_.distribution, wo, wi, mode);
  return {v.f, v.pdf};
}

// Accepts a local direction if it lies on the side of ng the lobe requires (wo's side when sameSide).
inline bool Bsdf::toWorldChecked(const Vec3& wi, bool sameSide, float go, Vec3* wiW) const {
  *wiW = frame_.toWorld(wi);
  const float gi = glm::dot(*wiW, ng_);
  return gi != 0.0f && (onPositiveSide(gi) == onPositiveSide(go)) == sameSide;
}

// A sampled rough direction, valued and weighted by the lobes as evaluate() would.
std::optional<BsdfSample> Bsdf::valuedSample(const Vec3& woW, const Vec3& wiW, TransportMode mode) const {
  const LobeValue v = evalLocal(*material_, frame_, ng_, alpha_, rough_.distribution, woW, wiW, mode);
  if (v.pdf <= 0.0f || isBlack(v.f)) return std::nullopt;
  return BsdfSample{wiW, v.f, v.pdf, false};
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& woW, const Vec2& u, float uLobe, TransportMode mode) const {
  const float go = glm::dot(woW, ng_);
  if (material_->kind == MaterialKind::Lambert) return sampleLambert(woW, go, u);
  const Vec3 wo = frame_.toLocal(woW);
  if (go == 0.0f || wo.z == 0.0f) return std::nullopt;
  const float side = wo.z > 0.0f ? 1.0f : -1.0f;
  const Outgoing out{woW, wo, Vec3(wo.x, wo.y, std::abs(wo.z)), side, go};
  if (material_->kind == MaterialKind::Conductor) return sampleConductor(out, u, mode);
  // Dielectric: +z is outside. wo's shading side must match its geometric side (it picks eta).
  if (wo.z * go <= 0.0f) return std::nullopt;
  const float etaRel = side > 0.0f ? material_->ior : 1.0f / material_->ior;  // eta on the far side / on wo's
  if (alpha_ == 0.0f) return sampleSmoothDielectric(out, etaRel, uLobe, mode);
  return sampleRoughDielectric(out, etaRel, u, uLobe, mode);
}

std::optional<BsdfSample> Bsdf::sampleLambert(const Vec3& woW, float go, const Vec2& u) const {
  const float woZ = glm::dot(woW, frame_.n);  // only wo's normal component matters
  if (go == 0.0f || woZ == 0.0f) return std::nullopt;
  Vec3 wi = cosineHemisphere(u);
  if (wi.z <= 0.0f) return std::nullopt;
  if (woZ < 0.0f) wi.z = -wi.z;
  Vec3 wiW;
  if (!toWorldChecked(wi, true, go, &wiW)) return std::nullopt;
  return BsdfSample{wiW, material_->baseColor * kInvPi, std::abs(wi.z) * kInvPi, false};
}

std::optional<BsdfSample> Bsdf::sampleConductor(const Outgoing& out, const Vec2& u, TransportMode mode) const {
  const Vec3& wo = out.local;
  const Vec3& woUp = out.up;
  const float go = out.go;
  Vec3 wiW;
  if (alpha_ == 0.0f) {
    // Perfect mirror: the delta's coefficient is F, divided by |cos wi| per BsdfSample's contract.
    if (!toWorldChecked(Vec3(-wo.x, -wo.y, wo.z), true, go, &wiW)) return std::nullopt;
    const Color f = fresnelSchlick(material_->baseColor, woUp.z) / woUp.z;
    if (!isFinite(f) || isBlack(f)) return std::nullopt;
    return BsdfSample{wiW, f, 1.0f, true};
  }
  const MicrofacetDistribution dist(rough_.distribution, alpha_);
  const Vec3 m = dist.sampleVisible(woUp, u);
  const float cosOm = glm::dot(woUp, m);
  if (cosOm <= 0.0f) return std::nullopt;
  Vec3 wi = 2.0f * cosOm * m - woUp;  // reflect about m (Walter Eq. 39)
  if (wi.z <= 0.0f) return std::nullopt;
  wi.z *= out.side;
  if (!toWorldChecked(wi, true, go, &wiW)) return std::nullopt;
  return valuedSample(out.world, wiW, mode);
}

std::optional<BsdfSample> Bsdf::sampleSmoothDielectric(const Outgoing& out, float etaRel, float uLobe,
                                                       TransportMode mode) const {
  const Material& mat = *material_;
  const Vec3& wo = out.local;
  const float woUpZ = out.up.z, side = out.side, go = out.go;
  const float fresnel = fresnelDielectric(wo.z, mat.ior);
  Vec3 wiW;
  if (uLobe < fresnel) {
    const float f = fresnel / woUpZ;
    if (!std::isfinite(f) || !toWorldChecked(Vec3(-wo.x, -wo.y, wo.z), true, go, &wiW)) return std::nullopt;
    return BsdfSample{wiW, Color(f), fresnel, true};
  }
  // Snell's law with the normal on wo's side; sin2T < 1 here since F < 1.
  const float sin2T = (1.0f - woUpZ * woUpZ) / (etaRel * etaRel);
  if (sin2T >= 1.0f) return std::nullopt;
  const float cosT = std::sqrt(1.0f - sin2T);
  if (!toWorldChecked(Vec3(-wo.x / etaRel, -wo.y / etaRel, -side * cosT), false, go, &wiW)) return std::nullopt;
  const float t = 1.0f - fresnel;
  // Radiance crossing into wo's medium scales by (eta_o / eta_i)^2 = 1 / etaRel^2 (Veach 1997 Sec. 5.2).
  const float scale = mode == TransportMode::Radiance ? t / (etaRel * etaRel * cosT) : t / cosT;
  const Color f = mat.baseColor * scale;
  if (!isFinite(f) || isBlack(f)) return std::nullopt;
  return BsdfSample{wiW, f, t, true};
}

std::optional<BsdfSample> Bsdf::sampleRoughDielectric(const Outgoing& out, float etaRel, const Vec2& u, float uLobe,
                                                      TransportMode mode) const {
  const Vec3& woUp = out.up;
  const MicrofacetDistribution dist(rough_.distribution, alpha_);
  const Vec3 mUp = dist.sampleVisible(woUp, u);
  const float cosOm = glm::dot(woUp, mUp);
  if (cosOm <= 0.0f) return std::nullopt;
  const float fresnel = fresnelDielectric(cosOm, etaRel);  // relative to wo's side
  Vec3 wi;
  if (uLobe < fresnel) {
    wi = 2.0f * cosOm * mUp - woUp;  // Walter Eq. 39
    if (wi.z <= 0.0f) return std::nullopt;
  } else {
    // Walter Eq. 40 in the frame mirrored to wo's side.
    const float sin2T = (1.0f - cosOm * cosOm) / (etaRel * etaRel);
    if (sin2T >= 1.0f) return std::nullopt;
    wi = -woUp / etaRel + (cosOm / etaRel - std::sqrt(1.0f - sin2T)) * mUp;
    if (wi.z >= 0.0f) return std::nullopt;
  }
  wi.z *= out.side;
  Vec3 wiW;
  if (!toWorldChecked(wi, uLobe < fresnel, out.go, &wiW)) return std::nullopt;
  return valuedSample(out.world, wiW, mode);
}

}  // namespace relt
