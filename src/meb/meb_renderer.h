#pragma once
// meb's iterations on one process (thesis digest §5.3, Figs. 6.8 and 6.10), over vcm's
// techniques: iteration i traces one stratified camera subpath per pixel and stores its vertices;
// evaluates an initial set of independent light subpaths against them (the normalisers b'_vis,
// b'_con, frozen for the iteration's weights, and the chains' start states); then chain pairs draw
// the iteration's N = pixels light subpaths. The light subpath techniques are weighted with
// kappa = 1 / b'_vis (the visibility chain's exact density factor, Eq. 6.7), and so are the
// camera subpaths' own techniques, so every path's weights sum to 1 for each chain (vcm_mis.h).
// Every random number is keyed by (seed, iteration, ...), so the image does not depend on which
// process or thread renders an iteration (up to the order of sums).
#include <cstdint>
#include <vector>

#include "film/film.h"
#include "meb/chain_pair.h"
#include "meb/initial_set.h"
#include "meb/meb_cameras.h"
#include "meb/meb_light_path.h"
#include "vcm/vcm_renderer.h"

namespace relt {

struct MebSettings {
  VcmSettings vcm;            // the merging radius and its shrinking (mode: every technique)
  int pairs = 16;             // chain pairs per iteration, whatever the threads
  // The initial set; 0: 10,000 (the thesis's, at 1280 x 720) or one per pixel if fewer, so that on
  // small images it does not cost more than the chains.
  int initialPaths = 0;
  float largeStepProbability = 0.3f;
};

// What an iteration's chains did, summed over iterations.
struct MebStats {
  uint64_t iterations = 0, withoutChains = 0;  // iterations whose initial set saw no light
  uint64_t steps[2] = {0, 0}, accepted[2] = {0, 0}, largeSteps = 0, exchanges = 0, exchangesTried = 0;
  uint64_t cameraVertices = 0, merges = 0, nonFinite = 0;
  double visibility = 0.0, contribution = 0.0, theta[2] = {0.0, 0.0};  // sums of b_vis, b_con, final thetas
  void add(const MebStats& o);
};

class MebRenderer {
 public:
  MebRenderer(const PathContext& ctx, const MebSettings& settings, uint64_t seed, int width, int height, int threads);

  // Adds iteration i's estimate of the image to `film`.
  void render(uint64_t iteration, Film& film);
  const MebStats& stats() const { return stats_; }
  double firstRadius() const { return radius1_; }

 private:
  using InitialSet = MebInitialSet<MebContribution>;
  InitialSet initialSet(const VcmTracer& tracer, uint64_t iteration);
  void rescore(InitialSet& set, const VcmTracer& tracer);
  NormaliserSums runChains(const VcmTracer& tracer, const InitialSet& set, const MebNormalisers& frozen,
                           uint64_t iteration, MebStats& stats);

  const PathContext& ctx_;
  MebSettings settings_;
  uint64_t seed_;
  int width_, height_, workers_;
  double radius1_;
  MebCameras cameras_;
  std::vector<Film> workerFilms_;     // the camera subpaths' own techniques
  std::vector<Film> chainFilms_[2];   // per worker, per chain
  MebStats stats_;
};

}  // namespace relt
