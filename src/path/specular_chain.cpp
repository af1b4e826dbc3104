#include "path/specular_chain.h"

#include "material/bsdf.h"

namespace relt {

void traceSpecularChain(const PathContext& ctx, const Vec2& film, SampleSource& source, PathSample& out) {
  Ray ray{ctx.camera.position(), ctx.camera.direction(film), INFINITY};
  Color beta(1.0f), direct(0.0f), throughSpecular(0.0f);
  for (int segments = 1;; ++segments) {
    SurfacePoint hit;
    float dist;
    if (!ctx.tracer.intersect(ray, hit, dist)) break;
    const Vec3 wo = -ray.dir;
    (segments == 1 ? direct : throughSpecular) += beta * ctx.lights.emitted(hit, wo);
    if (segments == ctx.settings.maxDepth) break;
    const Bsdf bsdf(ctx.scene.materials[hit.material], hit.ns, hit.ng);
    if (!bsdf.isDelta()) break;  // the rest of the path is the other estimators'
    // The same draws as a path tracer's at a delta vertex (no roulette: the chain is short).
    const Vec2 u = source.next2(SampleStream::Camera);
    const float uLobe = source.next(SampleStream::Camera);
    const auto bs = bsdf.sample(wo, u, uLobe, TransportMode::Radiance);
    if (!bs || !(bs->pdf > 0.0f)) break;
    beta *= bs->f * (std::abs(glm::dot(hit.ns, bs->wi)) / bs->pdf);
    if (isBlack(beta)) break;
    ray = ctx.tracer.spawn(hit, bs->wi);
  }
  out.add(film, throughSpecular, PathClass::L0);
  out.add(film, direct, PathClass::L1);
}

}  // namespace relt
