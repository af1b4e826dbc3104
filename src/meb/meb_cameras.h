#pragma once
// meb's camera subpaths of one iteration (thesis digest §5.3): one per pixel, independent and
// stratified (the pixel's point of a shifted (0,2)-sequence, as vcm's), their non-specular
// vertices stored with the state the light subpaths' techniques need, and a hash grid over them
// for merging. Their own techniques (emission found, next-event estimation) are kept with their
// weights apart until the iteration's light subpath factor is known.
#include <cstdint>
#include <span>
#include <vector>

#include "film/film.h"
#include "vcm/hash_grid.h"
#include "vcm/vcm_tracer.h"

namespace relt {

struct CameraVertex {
  SurfacePoint sp;
  Vec3 wo{0.0f};      // towards the previous vertex (the camera side)
  VcmSubpath state;   // the subpath on arrival here: beta, the MIS quantities, its length
  uint32_t pixel = 0;  // the subpath's
};

// Emission found or next-event estimation: its weight waits for kappa.
struct DeferredSplat {
  Vec2 film{0.0f};
  Color value{0.0f};  // unweighted
  CameraTechniqueWeight weight;
  PathClass cls = PathClass::L1;
};

class MebCameras {
 public:
  MebCameras(int width, int height, int workers);

  // Traces iteration i's camera subpaths (key: the seed) and indexes their vertices within `radius`.
  void trace(const VcmTracer& tracer, uint64_t seed, uint64_t iteration, float radius);
  // Adds the camera subpaths' own techniques, weighted with Mis(kappa) = kappaTerm, to `films`
  // (one per worker, as trace dealt the rows).
  void splatOwnTechniques(float kappaTerm, std::span<Film> films) const;

  uint32_t subpaths() const { return uint32_t(films_.size()); }
  std::span<const CameraVertex> subpath(uint32_t pixel) const { return paths_[pixel]; }
  const Vec2& film(uint32_t pixel) const { return films_[pixel]; }
  // Every stored vertex, copied in the grid's slot order: a light vertex's merges read their
  // camera vertices side by side (chasing them into the per-worker blocks cost more than merging).
  std::span<const CameraVertex> vertices() const { return bySlot_; }
  const HashGrid& grid() const { return grid_; }
  uint64_t vertexCount() const { return bySlot_.size(); }

 private:
  int width_, height_, workers_;
  std::vector<std::vector<CameraVertex>> workerVertices_;
  std::vector<std::vector<DeferredSplat>> workerDeferred_;
  std::vector<std::span<const CameraVertex>> paths_;  // by pixel
  std::vector<Vec2> films_;                           // by pixel
  std::vector<Vec3> positions_;  // in pixel order, for the grid
  std::vector<CameraVertex> bySlot_;
  HashGrid grid_;
};

}  // namespace relt
