#include "path/path_tracer.h"

#include "material/bsdf.h"

namespace relt {
namespace {

// Solid-angle density with which next-event estimation would have chosen this emitter point.
float lightPdfSolidAngle(const PathContext& ctx, const SurfacePoint& hit, const Vec3& wo, float dist) {
  const float cosL = std::abs(glm::dot(hit.ng, wo));
  if (cosL <= 0.0f) return 0.0f;
  const float pdfArea = ctx.lights.pdfPickTriangle(hit.triangle) / ctx.tracer.triangleArea(hit.triangle);
  return pdfArea * dist * dist / cosL;
}

float misWeight(float pdfA, float pdfB, MisHeuristic h) {
  const float a = misWeightTerm(pdfA, h), b = misWeightTerm(pdfB, h);
  return a > 0.0f ? a / (a + b) : 0.0f;
}

// Next-event estimation at a non-delta vertex: one light point, one shadow ray (class L2).
Color estimateDirect(const PathContext& ctx, const SurfacePoint& hit, const Bsdf& bsdf, const Vec3& wo,
                     SampleSource& source) {
  const float uPick = source.next(SampleStream::Light);
  const Vec2 uPos = source.next2(SampleStream::Light);
  const LightPoint lp = ctx.lights.samplePoint(uPick, uPos);
  Vec3 wi = lp.sp.p - hit.p;
  const float dist2 = glm::dot(wi, wi);
  if (!(dist2 > 0.0f)) return Color(0.0f);
  wi /= std::sqrt(dist2);

  Color li;
  float pdfLight;  // solid angle
  if (lp.delta) {
    li = ctx.lights.intensity(lp.light, -wi) / dist2;
    pdfLight = lp.pdfPick;
  } else {
    const float cosL = std::abs(glm::dot(lp.sp.ng, wi));
    li = ctx.lights.emitted(lp.sp, -wi);
    pdfLight = lp.pdfPick * lp.pdfPos * dist2 / cosL;
    if (!(cosL > 0.0f)) return Color(0.0f);
  }
  if (isBlack(li)) return Color(0.0f);
  const Bsdf::Value fv = bsdf.evaluate(wo, wi, TransportMode::Radiance);
  const Color f = fv.f * std::abs(glm::dot(hit.ns, wi));
  if (isBlack(f)) return Color(0.0f);
  const bool blocked = lp.delta ? ctx.tracer.occludedToPoint(hit.p, hit.ng, lp.sp.p)
                                : ctx.tracer.occluded(hit.p, hit.ng, lp.sp.p, lp.sp.ng);
  if (blocked) return Color(0.0f);
  const float w = lp.delta ? 1.0f : misWeight(pdfLight, fv.pdf, ctx.settings.heuristic);
  return f * li * (w / pdfLight);
}

}  // namespace

void tracePath(const PathContext& ctx, const Vec2& film, SampleSource& source, PathSample& out) {
  const int maxDepth = ctx.settings.maxDepth;
  Ray ray{ctx.camera.position(), ctx.camera.direction(film), INFINITY};
  Color beta(1.0f);
  Color byClass[3] = {Color(0.0f), Color(0.0f), Color(0.0f)};  // L0, L1, L2
  bool anySpecular = false, prevDelta = true;
  float prevPdf = 0.0f;

  for (int segments = 1; segments <= maxDepth; ++segments) {
    SurfacePoint hit;
    float dist;
    if (!ctx.tracer.intersect(ray, hit, dist)) break;
    const Vec3 wo = -ray.dir;

    const Color le = ctx.lights.emitted(hit, wo);
    if (!isBlack(le)) {
      // Emitters hit after a delta bounce (or seen directly) could not have been found by NEE.
      const float w = prevDelta ? 1.0f : misWeight(prevPdf, lightPdfSolidAngle(ctx, hit, wo, dist), ctx.settings.heuristic);
      byClass[anySpecular ? 0 : 1] += beta * le * w;
    }
    if (segments == maxDepth) break;

    const Material& material = ctx.scene.materials[hit.material];
    const Bsdf bsdf(material, hit.ns, hit.ng);
    if (!bsdf.isDelta() && !ctx.lights.empty()) byClass[2] += beta * estimateDirect(ctx, hit, bsdf, wo, source);

    const Vec2 u = source.next2(SampleStream::Camera);
    const float uLobe = source.next(SampleStream::Camera);
    const auto bs = bsdf.sample(wo, u, uLobe, TransportMode::Radiance);
    if (!bs || !(bs->pdf > 0.0f)) break;
    beta *= bs->f * (std::abs(glm::dot(hit.ns, bs->wi)) / bs->pdf);
    prevPdf = bs->pdf;
    prevDelta = bs->delta;
    anySpecular |= bs->delta;

    // Russian roulette on the throughput once the path is a few segments long.
    const float uRR = source.next(SampleStream::Camera);
    if (segments >= ctx.settings.rrDepth) {
      const float q = std::min(1.0f, maxComponent(beta));
      if (!(uRR < q)) break;
      beta /= q;
    }
    if (isBlack(beta)) break;
    ray = ctx.tracer.spawn(hit, bs->wi);
  }
  out.add(film, byClass[0], PathClass::L0);
  out.add(film, byClass[1], PathClass::L1);
  out.add(film, byClass[2], PathClass::L2);
}

}  // namespace relt
