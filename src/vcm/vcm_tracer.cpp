#include "vcm/vcm_tracer.h"

#include <cmath>

#include "path/vertex.h"

namespace relt {

bool VcmTracer::startLightPath(SampleSource& u, VcmSubpath& s) const {
  const float uPick = u.next(SampleStream::Light);
  const Vec2 uPos = u.next2(SampleStream::Light);
  const Vec2 uDir = u.next2(SampleStream::Light);
  if (ctx_.lights.empty()) return false;
  const LightPoint lp = ctx_.lights.samplePoint(uPick, uPos);
  const auto em = ctx_.lights.sampleDirection(lp, uDir);
  if (!(em.pdfDir > 0.0f)) return false;
  const Color le = lp.delta ? ctx_.lights.intensity(lp.light, em.dir) : ctx_.lights.emitted(lp.sp, em.dir);
  const float cosLight = lp.delta ? 1.0f : std::abs(glm::dot(lp.sp.ng, em.dir));
  const float pdfEmit = lp.pdfPick * lp.pdfPos * em.pdfDir;
  if (isBlack(le) || !(cosLight > 0.0f) || !(pdfEmit > 0.0f)) return false;
  s.beta = le * (cosLight / pdfEmit);
  mis_.startLight(s, lp, em.pdfDir, cosLight);
  s.origin = lp.delta ? lp.sp.p : ctx_.tracer.offsetOrigin(lp.sp.p, lp.sp.ng, em.dir);
  s.dir = em.dir;
  return true;
}

bool VcmTracer::advance(VcmSubpath& s, SurfacePoint& hit) const {
  float distance;
  if (!ctx_.tracer.intersect(Ray{s.origin, s.dir, INFINITY}, hit, distance)) return false;
  countSubpathVertices(ctx_, 1);
  return mis_.arrive(s, hit);
}

bool VcmTracer::scatter(const Bsdf& bsdf, const SurfacePoint& sp, const Vec3& wo, TransportMode mode, SampleSource& u,
                        SampleStream stream, VcmSubpath& s) const {
  const Vec2 uDir = u.next2(stream);
  const float uLobe = u.next(stream);
  const float uRR = u.next(stream);
  const auto bs = bsdf.sample(wo, uDir, uLobe, mode);
  if (!bs || !(bs->pdf > 0.0f)) return false;
  const float q = continuationProbability(bsdf.material());
  if (!(uRR < q)) return false;
  float scale = std::abs(glm::dot(sp.ns, bs->wi)) / (bs->pdf * q);
  if (mode == TransportMode::Importance) scale *= shadingCorrection(sp, wo, bs->wi);
  s.beta *= bs->f * scale;
  if (isBlack(s.beta) || !isFinite(s.beta)) return false;
  if (!mis_.scatter(s, bsdf, sp, wo, bs->wi)) return false;
  const Ray ray = ctx_.tracer.spawn(sp, bs->wi);
  s.origin = ray.origin;
  s.dir = ray.dir;
  return true;
}

void VcmTracer::traceLightPath(SampleSource& u, std::vector<LightVertex>& store, PathSample& splats) const {
  VcmSubpath s;
  if (!startLightPath(u, s)) return;
  const int maxDepth = ctx_.settings.maxDepth;
  // A vertex serves a technique up to maxDepth - 1 segments from the light (merging, light tracing).
  while (s.length < maxDepth - 1) {
    SurfacePoint hit;
    if (!advance(s, hit)) return;
    const Vec3 wo = -s.dir;  // the traced ray's, as bdpt samples with (path/vertex.h)
    const Bsdf bsdf(ctx_.scene.materials[hit.material], hit.ns, hit.ng);
    if (!bsdf.isDelta()) {
      store.push_back(LightVertex{hit, wo, s.beta, s.dVCM, s.dVC, s.dVM, s.length});
      if (mis_.connects()) connectToCamera(store.back(), bsdf, splats);
    }
    if (s.length >= maxDepth - 1 || !scatter(bsdf, hit, wo, TransportMode::Importance, u, SampleStream::Light, s))
      return;
  }
}

// Light tracing (t = 1): the vertex seen through the pinhole, splatted where it lands.
void VcmTracer::connectToCamera(const LightVertex& y, const Bsdf& bsdf, PathSample& splats) const {
  const Vec3 toCamera = ctx_.camera.position() - y.sp.p;
  const float dist2 = glm::dot(toCamera, toCamera);
  if (!(dist2 > 0.0f)) return;
  const Vec3 w = toCamera / std::sqrt(dist2);
  const auto fp = ctx_.camera.filmPosition(-w);
  if (!fp) return;
  const Color f = bsdf.eval(y.wo, w, TransportMode::Importance) * shadingCorrection(y.sp, y.wo, w);
  if (isBlack(f)) return;
  const float cosCamera = glm::dot(ctx_.camera.forward(), -w);
  const Color value =
      y.beta * f * (std::abs(glm::dot(y.sp.ns, w)) * cosCamera / dist2 * ctx_.camera.importance(-w));
  if (ctx_.tracer.occludedToPoint(y.sp.p, y.sp.ng, ctx_.camera.position())) return;
  splats.add(*fp, value * mis_.lightTracingWeight(y, bsdf), PathClass::L4);
}

}  // namespace relt
