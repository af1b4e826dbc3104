#pragma once
// A scene ready to render: loaded, validated, with its acceleration structure, lights and camera,
// and the independent-sample integrators (pt, bdpt) over units of work. The distributed layer
// decides which rank renders which unit; the image depends only on the seed and which units were
// rendered, never on who rendered them.
#include <array>
#include <memory>

#include "film/film.h"
#include "image/image.h"
#include "path/bdpt.h"
#include "path/path_tracer.h"
#include "render/settings.h"

namespace relt {

// How renderRow estimates a pixel sample: a path traced from the camera (pixels of a row in
// packets), or bidirectionally (light subpaths connected to it, splatting anywhere).
enum class RowEstimator : uint8_t { PathTracing, Bidirectional };

class Renderer {
 public:
  // Takes a loaded scene; throws InputError if it cannot be rendered with these settings.
  Renderer(Scene scene, const RenderSettings& settings);
  Renderer(const Renderer&) = delete;  // the ray tracer refers to scene_
  Renderer& operator=(const Renderer&) = delete;

  const Scene& scene() const { return scene_; }
  const Camera& camera() const { return *camera_; }
  const RenderSettings& settings() const { return settings_; }
  const PathContext& context() const { return *ctx_; }

  // One unit of work: sample `sampleIndex` of every pixel of row `row`. Each pixel sample has its
  // own random stream keyed by (seed, pixel, sample index). Worker threads of the rank
  // (settings().threads, parallel/workers.h) may render rows at once, each into a film of its own.
  void renderRow(RowEstimator estimator, uint64_t sampleIndex, int row, Film& film);
  // The emission seen directly or through specular surfaces only (path/specular_chain.h) of rows
  // firstRow, firstRow + rowStride, ...:
  // camera rays number begin .. end - 1 of every pixel, at the points of a shifted (0,2)-sequence,
  // on streams of their own; after rays 0 .. N - 1, resolve with divisor N (render/direct_pass.h
  // decides N). `probe` traces on streams apart again: rays that decide whether the pass runs
  // must not be part of its estimate. On the rank's worker threads; the film is the same for any
  // number of them.
  void renderDirect(int firstRow, int rowStride, Film& film, uint32_t begin, uint32_t end, bool probe = false);
  // The direct pass saw none of that emission: the main estimator takes those paths again.
  // Only before any chain has stepped.
  void keepDirectEmissionInChains();

  uint64_t samples() const;
  uint64_t rays() const { return tracer_->rayCount(); }
  // Surface vertices the bidirectional subpaths reached (path/path_context.h).
  uint64_t subpathVertices() const { return subpathVertices_.total(); }

  // Film sums -> pixel values for `spp` samples per pixel.
  static Image resolve(const Film& film, const std::vector<double>& sums, double spp);
  // The same for passes stopped inside one: rows below `rowsAhead` have passes + 1 samples.
  static Image resolve(const Film& film, const std::vector<double>& sums, int passes, int rowsAhead);

 private:
  Scene scene_;
  RenderSettings settings_;
  std::unique_ptr<RayTracer> tracer_;
  std::unique_ptr<LightSampler> lights_;
  std::unique_ptr<Camera> camera_;
  std::unique_ptr<PathContext> ctx_;
  PerWorkerCount subpathVertices_;
  // What one worker thread's rows need of their own: a batch of neighbouring pixels (traced
  // together, see tracePaths), bdpt's subpaths, and the samples it took.
  struct RowWorker {
    explicit RowWorker(const PathContext& ctx);
    std::array<IndependentSource, RayTracer::kPacketSize> sources{};
    std::array<SampleSource*, RayTracer::kPacketSize> sourcePointers{};
    std::array<PathSample, RayTracer::kPacketSize> samples{};
    Bdpt bdpt;
    uint64_t sampleCount = 0;
  };
  std::vector<std::unique_ptr<RowWorker>> workers_;
  // renderDirect's samples of one row; returns how many were not finite (not added).
  uint64_t renderDirectRow(uint64_t stream, int row, Film& film, uint32_t begin, uint32_t end,
                           IndependentSource& source, PathSample& sample) const;
  static constexpr uint64_t kDirectStream = 0xd12ec7;  // keeps renderDirect's streams apart
  static constexpr uint64_t kProbeStream = 0xd12ec8;   // and the probe's from those
};

// Applies the scene's defaults to settings left unset (width/height/max depth 0).
void resolveDefaults(const Scene& scene, RenderSettings& settings);

}  // namespace relt
