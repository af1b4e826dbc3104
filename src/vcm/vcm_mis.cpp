#include "vcm/vcm_mis.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "path/vertex.h"

namespace relt {

std::optional<VcmMode> parseVcmMode(std::string_view name) {
  if (name == "vcm") return VcmMode::Vcm;
  if (name == "bpt") return VcmMode::Bpt;
  if (name == "ppm") return VcmMode::Ppm;
  return std::nullopt;
}

const char* vcmModeName(VcmMode mode) {
  switch (mode) {
    case VcmMode::Bpt: return "bpt";
    case VcmMode::Ppm: return "ppm";
    default: return "vcm";
  }
}

VcmMis::VcmMis(const PathContext& ctx, const VcmIteration& iteration)
    : ctx_(ctx), mode_(iteration.mode), kappa_(mis(float(iteration.lightSubpathFactor))) {
  const double eta = std::numbers::pi * double(iteration.radius) * iteration.radius * iteration.lightPaths;
  if (merges() && eta > 0.0) {
    vmWeight_ = connects() ? mis(float(eta)) : 0.0f;
    vcWeight_ = connects() ? mis(float(1.0 / eta)) : 0.0f;
    mergeNormalisation_ = 1.0 / eta;
  }
}

void VcmMis::startLight(VcmSubpath& s, const LightPoint& lp, float pdfDir, float cosLight) const {
  const float pdfStart = lp.pdfPick * lp.pdfPos, pdfEmit = pdfStart * pdfDir;
  // dVCM and dVC start the terms of next-event estimation and of emission found (s = 1, 0): the
  // only techniques without the light subpath factor, so only they are divided by it.
  s.dVCM = mis(pdfStart / pdfEmit) / kappa_;
  s.dVC = lp.delta ? 0.0f : mis(cosLight / pdfEmit) / kappa_;  // a point light's position cannot be hit
  s.dVM = s.dVC * vcWeight_;
  s.last = lp.sp.p;
  s.length = 0;
}

void VcmMis::startCamera(VcmSubpath& s, float pdfCamera) const {
  s.dVCM = mis(1.0f / pdfCamera);  // N_L / (the pixel's density): one light subpath per camera sample
  s.dVC = s.dVM = 0.0f;
  s.last = ctx_.camera.position();
  s.length = 0;
  s.specular = true;
}

bool VcmMis::arrive(VcmSubpath& s, const SurfacePoint& hit) const {
  const Vec3 d = hit.p - s.last;
  const float dist2 = glm::dot(d, d);
  const float cosIn = dist2 > 0.0f ? std::abs(glm::dot(hit.ng, d)) / std::sqrt(dist2) : 0.0f;
  if (!(cosIn > 0.0f)) return false;
  ++s.length;
  s.dVCM *= mis(dist2);
  const float c = mis(cosIn);
  s.dVCM /= c;
  s.dVC /= c;
  s.dVM /= c;
  return true;
}

bool VcmMis::scatter(VcmSubpath& s, const Bsdf& bsdf, const SurfacePoint& sp, const Vec3& wo, const Vec3& wi) const {
  const float cosOut = std::abs(glm::dot(sp.ng, wi));
  s.last = sp.p;
  if (bsdf.isDelta()) {  // the densities both ways are the same delta: only the cosine stays
    s.dVCM = 0.0f;
    s.dVC *= mis(cosOut);
    s.dVM *= mis(cosOut);
    return true;
  }
  const float q = continuationProbability(bsdf.material());
  const float pdfDir = bsdf.pdf(wo, wi) * q, pdfRev = bsdf.pdf(wi, wo) * q;
  if (!(pdfDir > 0.0f)) return false;
  const float k = mis(cosOut / pdfDir);
  s.dVC = k * (s.dVC * mis(pdfRev) + s.dVCM + vmWeight_);
  s.dVM = k * (s.dVM * mis(pdfRev) + s.dVCM * vcWeight_ + 1.0f);
  s.dVCM = mis(1.0f / pdfDir);
  s.specular = false;
  return true;
}

// Seen straight from the pinhole, only this technique makes the path; with merging only, every path
// through a non-specular camera vertex is merged there instead.
CameraTechniqueWeight VcmMis::emissionWeightParts(const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo) const {
  if (s.length == 1) return {};
  if (mode_ == VcmMode::Ppm) return {0.0f, 0.0f, s.specular};
  const uint32_t light = ctx_.lights.lightOfTriangle(hit.triangle);
  if (light == std::numeric_limits<uint32_t>::max()) return {0.0f, 0.0f, false};
  const float pdfStart = ctx_.lights.pdfPick(light) * ctx_.lights.pdfPosition(light);
  const float pdfEmit = pdfStart * ctx_.lights.pdfDirection(light, hit, wo);
  return {mis(pdfStart) * s.dVCM, mis(pdfEmit) * s.dVC};
}

CameraTechniqueWeight VcmMis::nextEventWeightParts(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo,
                                                   const Bsdf& bsdf, const LightPoint& lp) const {
  const Vec3 d = lp.sp.p - x.p;
  const float dist2 = glm::dot(d, d);
  const Vec3 w = d / std::sqrt(dist2);
  const float cosAtLight = lp.delta ? 1.0f : std::abs(glm::dot(lp.sp.ng, w));
  const float q = continuationProbability(bsdf.material());
  const float pdfLightW = lp.pdfPick * lp.pdfPos * dist2 / cosAtLight;  // the light point's, seen from x
  const float pdfHitW = lp.delta ? 0.0f : bsdf.pdf(wo, w) * q;          // the camera subpath hitting it
  const float pdfEmitA = ctx_.lights.pdfDirection(lp.light, lp.sp, -w) * std::abs(glm::dot(x.ng, w)) / dist2;
  return {mis(pdfHitW / pdfLightW), mis(pdfEmitA) * (vmWeight_ + s.dVCM + s.dVC * mis(bsdf.pdf(w, wo) * q))};
}

float VcmMis::connectWeight(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                            const LightVertex& y, const Bsdf& atY) const {
  const Vec3 d = y.sp.p - x.p;
  const float dist2 = glm::dot(d, d);
  const Vec3 w = d / std::sqrt(dist2);
  const float qC = continuationProbability(bsdf.material()), qL = continuationProbability(atY.material());
  const float cameraPdfA = bsdf.pdf(wo, w) * qC * std::abs(glm::dot(y.sp.ng, w)) / dist2;
  const float lightPdfA = atY.pdf(y.wo, -w) * qL * std::abs(glm::dot(x.ng, w)) / dist2;
  const float wLight = mis(cameraPdfA) * (vmWeight_ + y.dVCM + y.dVC * mis(atY.pdf(-w, y.wo) * qL));
  const float wCamera = mis(lightPdfA) * (vmWeight_ + s.dVCM + s.dVC * mis(bsdf.pdf(w, wo) * qC));
  return 1.0f / (wLight + 1.0f + wCamera);
}

float VcmMis::lightTracingWeight(const LightVertex& y, const Bsdf& atY) const {
  const Vec3 toCamera = ctx_.camera.position() - y.sp.p;
  const float dist2 = glm::dot(toCamera, toCamera);
  const Vec3 w = toCamera / std::sqrt(dist2);
  const float q = continuationProbability(atY.material());
  const float cameraPdfA = ctx_.camera.pdfDirection(-w) * std::abs(glm::dot(y.sp.ng, w)) / dist2;
  return 1.0f / (mis(cameraPdfA) * (vmWeight_ + y.dVCM + y.dVC * mis(atY.pdf(w, y.wo) * q)) + 1.0f);
}

// The camera subpath continuing from its vertex (leaving towards wo) to y's predecessor, and back.
float VcmMis::mergeWeight(const VcmSubpath& s, const Vec3& wo, const Bsdf& bsdf, const LightVertex& y) const {
  if (mode_ == VcmMode::Ppm) return 1.0f;  // one technique per path
  const float qC = continuationProbability(bsdf.material());
  const float qL = continuationProbability(ctx_.scene.materials[y.sp.material]);
  const float wLight = y.dVCM * vcWeight_ + y.dVM * mis(bsdf.pdf(wo, y.wo) * qC);
  const float wCamera = s.dVCM * vcWeight_ + s.dVM * mis(bsdf.pdf(y.wo, wo) * qL);
  return 1.0f / (wLight + 1.0f + wCamera);
}

}  // namespace relt
