#pragma once
// VCM's iterations on one process (vcm_tracer.h): iteration i traces one light subpath per pixel,
// indexes their vertices for merging, then traces one camera subpath per pixel, on the process's
// worker threads. Every random number is keyed by (seed, iteration, path), so an iteration's
// estimate is the same whichever process and threads render it (up to the order of sums).
#include <cstdint>
#include <span>
#include <vector>

#include "film/film.h"
#include "parallel/workers.h"
#include "vcm/vcm_tracer.h"

namespace relt {

struct VcmSettings {
  VcmMode mode = VcmMode::Vcm;
  // The first iteration's merging radius, in pixel footprints (pixelFootprint): the least error at
  // 30 s over five scenes (docs/BENCHMARKS.md, "vcm's merging radius"), within 1.2x of each one's best.
  double radius = 1.0;
  double alpha = 0.75;    // r_i = r_1 i^((alpha - 1) / 2): the radius shrinks, the bias vanishes
};

// The width a pixel covers at the median distance of the first hits of camera rays through a 16 x
// 16 grid over the film: merging within a few of them blurs the light by about as many pixels,
// whatever the resolution, and the light vertices within the radius stay as many.
double pixelFootprint(const PathContext& ctx);
// The merging radius of iteration i (from 0) for a first radius r1.
double vcmRadius(double r1, double alpha, uint64_t iteration);

class VcmRenderer {
 public:
  VcmRenderer(const PathContext& ctx, const VcmSettings& settings, uint64_t seed, int width, int height, int threads);

  // Adds iteration i's estimate of the image to `film` (the image: the sum over iterations divided
  // by their number).
  void render(uint64_t iteration, Film& film);
  // Light vertices stored over the iterations this process rendered.
  uint64_t lightVertices() const { return lightVertices_; }
  // Light vertices merged with (within the radius of a camera vertex, the path no longer than the
  // maximum depth) over those iterations.
  uint64_t merges() const { return merges_.total(); }
  double firstRadius() const { return radius1_; }

 private:
  void traceLightPaths(const VcmTracer& tracer, uint64_t iteration);
  void indexForMerging(float radius);
  void traceCameraPaths(const VcmTracer& tracer, uint64_t iteration, const HashGrid* grid);

  const PathContext& ctx_;
  VcmSettings settings_;
  uint64_t seed_;
  int width_, height_, workers_;
  double radius1_;
  std::vector<std::vector<LightVertex>> workerVertices_;  // worker w's block of light subpaths, kept there
  std::vector<std::span<const LightVertex>> paths_;       // light subpath j's vertices
  std::vector<Vec3> positions_;                           // every light vertex's, by path: the grid's input
  std::vector<LightVertex> bySlot_;                       // the light vertices again, in the grid's slot order
  std::vector<Film> workerFilms_;
  HashGrid grid_;
  uint64_t lightVertices_ = 0;
  PerWorkerCount merges_;
};

}  // namespace relt
