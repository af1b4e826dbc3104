#pragma once
// Vertex connection and merging (Georgiev et al. 2012; Hachisuka et al. 2012): per iteration, one
// light subpath per pixel, stored; then one camera subpath per pixel that takes every technique at
// each vertex: emission found (s = 0), next-event estimation, connections to the vertices of one
// light subpath, and merging with the iteration's light vertices within radius r. The light
// subpaths are also connected to the camera (light tracing). MIS over all of them follows the
// recursive quantities dVCM, dVC, dVM of each subpath (thesis digest §1.6).
//
// Densities are relt's film-wide ones (as Bdpt's): the camera's direction density is that of one
// sample over the whole film, and each camera sample has one light subpath to connect to, so light
// tracing splats count as BDPT's do. Area conversions use geometric normals, throughput cosines
// shading normals (as Bdpt).
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/sample_source.h"
#include "material/bsdf.h"
#include "path/path_context.h"
#include "path/splat.h"
#include "vcm/hash_grid.h"

namespace relt {

enum class VcmMode : uint8_t {
  Vcm,  // every technique
  Bpt,  // connections only: bdpt's estimator
  Ppm,  // merging only at the first non-specular camera vertex: progressive photon mapping
};
std::optional<VcmMode> parseVcmMode(std::string_view name);
const char* vcmModeName(VcmMode mode);

// What the techniques of one iteration need to know.
struct VcmIteration {
  VcmMode mode = VcmMode::Vcm;
  float radius = 0.0f;      // merging radius r
  double lightPaths = 1.0;  // N_L, the light subpaths traced in the iteration
};

// A stored vertex of a light subpath (non-specular surfaces only).
struct LightVertex {
  SurfacePoint sp;
  Vec3 wo{0.0f};    // towards the previous vertex of its subpath
  Color beta{0.0f};  // throughput from the light to here
  float dVCM = 0.0f, dVC = 0.0f, dVM = 0.0f;
  int length = 0;  // segments from the light
};

// The MIS state of a subpath while it is traced.
struct VcmSubpath {
  Vec3 origin{0.0f}, dir{0.0f}, last{0.0f};  // the next ray, and the last vertex's position
  Color beta{1.0f};
  float dVCM = 0.0f, dVC = 0.0f, dVM = 0.0f;
  int length = 0;
  bool specular = true;  // camera: every scattering so far was specular
};

class VcmTracer {
 public:
  VcmTracer(const PathContext& ctx, const VcmIteration& iteration);

  // Traces one light subpath: appends its stored vertices to `store` and adds its light-tracing
  // splats to `splats`.
  void traceLightPath(SampleSource& u, std::vector<LightVertex>& store, PathSample& splats) const;
  // Traces the camera subpath through `film` (pixels): its contributions go to `out`. It connects
  // to `own` (the vertices of one light subpath) and merges with the vertices `grid` indexes in
  // `all` (null grid: no merging).
  void traceCameraPath(const Vec2& film, SampleSource& u, std::span<const LightVertex> own,
                       std::span<const LightVertex> all, const HashGrid* grid, PathSample& out) const;

 private:
  float mis(float v) const { return misWeightTerm(v, ctx_.settings.heuristic); }
  bool connects() const { return iteration_.mode != VcmMode::Ppm; }
  bool merges() const { return iteration_.mode != VcmMode::Bpt; }
  bool startLightPath(SampleSource& u, VcmSubpath& s) const;
  // Samples the next direction at a surface vertex and updates the MIS state; false: the subpath ends.
  bool scatter(const Bsdf& bsdf, const SurfacePoint& sp, const Vec3& wo, TransportMode mode, SampleSource& u,
               SampleStream stream, VcmSubpath& s) const;
  // Traces the subpath's next segment and converts the MIS state to `hit` (the segment's squared
  // length and cosine there); false: it leaves the scene.
  bool arrive(VcmSubpath& s, SurfacePoint& hit) const;
  void connectToCamera(const LightVertex& y, const Bsdf& bsdf, PathSample& splats) const;
  float emissionWeight(const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo) const;
  Color nextEvent(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf, SampleSource& u) const;
  Color connect(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf, const LightVertex& y) const;
  Color merge(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
              std::span<const LightVertex> all, const HashGrid& grid) const;

  const PathContext& ctx_;
  VcmIteration iteration_;
  float vmWeight_ = 0.0f, vcWeight_ = 0.0f;  // Mis(eta) and Mis(1 / eta), eta = pi r^2 N_L
  double mergeNormalisation_ = 0.0;           // 1 / (pi r^2 N_L)
};

}  // namespace relt
