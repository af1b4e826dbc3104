#pragma once
// Vertex connection and merging (Georgiev et al. 2012; Hachisuka et al. 2012): per iteration, one
// light subpath per pixel, stored; then one camera subpath per pixel that takes every technique at
// each vertex: emission found (s = 0), next-event estimation, connections to the vertices of one
// light subpath, and merging with the iteration's light vertices within radius r. The light
// subpaths are also connected to the camera (light tracing). The MIS over all of them is VcmMis's.
#include <span>
#include <vector>

#include "core/sample_source.h"
#include "path/splat.h"
#include "vcm/hash_grid.h"
#include "vcm/vcm_mis.h"

namespace relt {

// A contribution of next-event estimation whose weight waits for the light subpath factor.
struct WeightedLater {
  Color value{0.0f};  // unweighted
  CameraTechniqueWeight weight{0.0f, 0.0f, false};
};

class VcmTracer {
 public:
  // `merges` (optional) counts the light vertices merged with.
  VcmTracer(const PathContext& ctx, const VcmIteration& iteration, PerWorkerCount* merges = nullptr)
      : ctx_(ctx), mis_(ctx, iteration), merges_(merges) {}

  // Traces one light subpath: appends its stored vertices to `store` and adds its light-tracing
  // splats to `splats`.
  void traceLightPath(SampleSource& u, std::vector<LightVertex>& store, PathSample& splats) const;
  // Traces the camera subpath through `film` (pixels): its contributions go to `out`. It connects
  // to `own` (the vertices of one light subpath) and merges with the vertices `grid` indexes,
  // `bySlot` holding them in the grid's slot order (null grid: no merging).
  void traceCameraPath(const Vec2& film, SampleSource& u, std::span<const LightVertex> own,
                       std::span<const LightVertex> bySlot, const HashGrid* grid, PathSample& out) const;

  // The camera subpath through `film`, vertex by vertex: onEmitter(s, hit, wo, le) where it finds
  // emission le (not after specular vertices only when the pass apart estimates those paths), onSurface(s, hit, wo, bsdf) at every non-specular vertex (false: the subpath ends
  // there). s is the subpath's state on arrival.
  template <class OnEmitter, class OnSurface>
  void walkCamera(const Vec2& film, SampleSource& u, OnEmitter&& onEmitter, OnSurface&& onSurface) const;

  // The techniques one camera vertex x (state s, leaving towards wo) takes, for meb, which calls
  // them from either end: next-event estimation with its weight kept apart; x joined to light
  // vertex y (weighted); merging with y: f y.beta times its weight, which the caller multiplies
  // by s.beta and mis().mergeNormalisation().
  WeightedLater nextEventLater(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                               SampleSource& u) const;
  Color connect(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf, const LightVertex& y) const;
  Color mergeOne(const VcmSubpath& s, const Vec3& wo, const Bsdf& bsdf, const LightVertex& y) const;
  const VcmMis& mis() const { return mis_; }

 private:
  bool startLightPath(SampleSource& u, VcmSubpath& s) const;
  // Traces the subpath's next segment to `hit`; false: it leaves the scene.
  bool advance(VcmSubpath& s, SurfacePoint& hit) const;
  // Samples the next direction at a surface vertex; false: the subpath ends.
  bool scatter(const Bsdf& bsdf, const SurfacePoint& sp, const Vec3& wo, TransportMode mode, SampleSource& u,
               SampleStream stream, VcmSubpath& s) const;
  void connectToCamera(const LightVertex& y, const Bsdf& bsdf, PathSample& splats) const;
  Color merge(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
              std::span<const LightVertex> bySlot, const HashGrid& grid) const;

  const PathContext& ctx_;
  VcmMis mis_;
  PerWorkerCount* merges_;
};

template <class OnEmitter, class OnSurface>
void VcmTracer::walkCamera(const Vec2& film, SampleSource& u, OnEmitter&& onEmitter, OnSurface&& onSurface) const {
  VcmSubpath s;
  s.dir = ctx_.camera.direction(film);
  const float pdfCamera = ctx_.camera.pdfDirection(s.dir);
  if (!(pdfCamera > 0.0f)) return;
  mis_.startCamera(s, pdfCamera);
  s.origin = s.last;
  const int maxDepth = ctx_.settings.maxDepth;
  while (true) {
    SurfacePoint hit;
    if (!advance(s, hit)) return;
    const Vec3 wo = -s.dir;  // the traced ray's, as bdpt samples with (path/vertex.h)
    const Color le = ctx_.lights.emitted(hit, wo);
    // Found after specular vertices only, it may be the pass apart's (path/specular_chain.h).
    if (!isBlack(le) && !(s.specular && ctx_.settings.specularChainsApart)) onEmitter(static_cast<const VcmSubpath&>(s), hit, wo, le);
    if (s.length >= maxDepth) return;
    const Bsdf bsdf(ctx_.scene.materials[hit.material], hit.ns, hit.ng);
    if (!bsdf.isDelta() && !onSurface(static_cast<const VcmSubpath&>(s), hit, wo, bsdf)) return;
    if (!scatter(bsdf, hit, wo, TransportMode::Radiance, u, SampleStream::Camera, s)) return;
  }
}

}  // namespace relt
