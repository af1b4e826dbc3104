#include "meb/meb_light_path.h"

#include <algorithm>

namespace relt {

MebContribution MebLightPath::operator()(SampleSource& u) {
  MebContribution c;
  const uint32_t count = cameras_.subpaths();
  const uint32_t pixel = std::min(uint32_t(u.next(SampleStream::Connection) * float(count)), count - 1);
  vertices_.clear();
  tracer_.traceLightPath(u, vertices_, c.sample);
  for (const LightVertex& y : vertices_) {
    if (tracer_.mis().connects()) connect(y, pixel, c.sample);
    if (tracer_.mis().merges()) merge(y, c.sample);
  }
  if (!c.sample.finite()) {
    ++nonFinite_;
    c.sample.clear();
  }
  return c;
}

// Light vertex y joined to every vertex of camera subpath `pixel`.
void MebLightPath::connect(const LightVertex& y, uint32_t pixel, PathSample& out) const {
  const int maxDepth = ctx_.settings.maxDepth;
  Color sum(0.0f);
  for (const CameraVertex& x : cameras_.subpath(pixel)) {
    if (y.length + x.state.length + 1 > maxDepth) continue;
    const Bsdf bsdf(ctx_.scene.materials[x.sp.material], x.sp.ns, x.sp.ng);
    sum += tracer_.connect(x.state, x.sp, x.wo, bsdf, y);
  }
  out.add(cameras_.film(pixel), sum, PathClass::L5);
}

// y merged with the camera vertices within the radius, each splatted at its own pixel.
void MebLightPath::merge(const LightVertex& y, PathSample& out) {
  const int maxDepth = ctx_.settings.maxDepth;
  const float normalisation = float(tracer_.mis().mergeNormalisation());
  const std::span<const CameraVertex> all = cameras_.vertices();
  cameras_.grid().forEachSlotNear(y.sp.p, [&](uint32_t slot) {
    const CameraVertex& x = all[slot];
    if (y.length + x.state.length > maxDepth) return;
    ++merges_;
    const Bsdf bsdf(ctx_.scene.materials[x.sp.material], x.sp.ns, x.sp.ng);
    const Color value = x.state.beta * tracer_.mergeOne(x.state, x.wo, bsdf, y) * normalisation;
    out.add(cameras_.film(x.pixel), value, PathClass::L5);
  });
}

}  // namespace relt
