#include "vcm/vcm_renderer.h"

#include <algorithm>
#include <cmath>

#include "camera/film_position.h"
#include "core/low_discrepancy.h"
#include "core/rng.h"
#include "parallel/workers.h"

namespace relt {
namespace {

constexpr uint64_t kLightPathPurpose = 0x7c41, kCameraPathPurpose = 0x7c43, kPixelShiftPurpose = 0x7c47;

}  // namespace

double pixelFootprint(const PathContext& ctx) {
  const Camera& camera = ctx.camera;
  const int w = camera.width(), h = camera.height();
  std::vector<float> distances;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const Vec2 film((float(i) + 0.5f) * float(w) / 16.0f, (float(j) + 0.5f) * float(h) / 16.0f);
      SurfacePoint hit;
      float distance;
      if (ctx.tracer.intersect(Ray{camera.position(), camera.direction(film), INFINITY}, hit, distance))
        distances.push_back(distance);
    }
  if (distances.empty()) return 1e-3 * double(glm::length(ctx.scene.bounds.diagonal()));
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  const Vec2 centre(float(w) / 2.0f, float(h) / 2.0f);
  const float angle = glm::length(camera.direction(centre + Vec2(1.0f, 0.0f)) - camera.direction(centre));
  return double(distances[distances.size() / 2]) * double(angle);
}

double vcmRadius(double r1, double alpha, uint64_t iteration) {
  return r1 * std::pow(double(iteration + 1), 0.5 * (alpha - 1.0));
}

VcmRenderer::VcmRenderer(const PathContext& ctx, const VcmSettings& settings, uint64_t seed, int width, int height,
                         int threads)
    : ctx_(ctx),
      settings_(settings),
      seed_(seed),
      width_(width),
      height_(height),
      workers_(std::max(threads, 1)),
      radius1_(settings.radius * pixelFootprint(ctx)),
      workerVertices_(size_t(workers_)) {
  for (int w = 0; w < workers_; ++w) workerFilms_.emplace_back(width, height);
}

void VcmRenderer::render(uint64_t iteration, Film& film) {
  VcmIteration it;
  it.mode = settings_.mode;
  it.radius = float(vcmRadius(radius1_, settings_.alpha, iteration));
  it.lightPaths = double(width_) * height_;
  const VcmTracer tracer(ctx_, it, &merges_);
  traceLightPaths(tracer, iteration);
  const bool merging = settings_.mode != VcmMode::Bpt && it.radius > 0.0f;
  if (merging) indexForMerging(it.radius);
  traceCameraPaths(tracer, iteration, merging ? &grid_ : nullptr);
  for (Film& f : workerFilms_) {  // in worker order
    film.addWeighted(f, 1.0);
    f.clear();
  }
  lightVertices_ += positions_.size();
}

// Worker w traces a contiguous block of the light subpaths into its own store; the connections
// find a subpath's vertices there, through spans in subpath order.
void VcmRenderer::traceLightPaths(const VcmTracer& tracer, uint64_t iteration) {
  const uint32_t paths = uint32_t(width_) * uint32_t(height_);
  std::vector<std::vector<uint32_t>> starts(static_cast<size_t>(workers_));
  runOnWorkers(workers_, [&](int w) {
    std::vector<LightVertex>& mine = workerVertices_[size_t(w)];
    mine.clear();
    starts[size_t(w)].clear();
    PathSample splats;
    const uint32_t first = uint32_t(uint64_t(paths) * w / workers_), end = uint32_t(uint64_t(paths) * (w + 1) / workers_);
    for (uint32_t j = first; j < end; ++j) {
      starts[size_t(w)].push_back(uint32_t(mine.size()));
      IndependentSource u(hashKey(seed_, kLightPathPurpose, iteration, j));
      splats.clear();
      tracer.traceLightPath(u, mine, splats);
      workerFilms_[size_t(w)].addSample(splats);
    }
  });
  positions_.clear();
  paths_.clear();
  for (int w = 0; w < workers_; ++w) {
    const std::vector<LightVertex>& block = workerVertices_[size_t(w)];
    const std::vector<uint32_t>& start = starts[size_t(w)];
    for (size_t j = 0; j < start.size(); ++j)
      paths_.emplace_back(block.data() + start[j], (j + 1 < start.size() ? start[j + 1] : block.size()) - start[j]);
    for (const LightVertex& v : block) positions_.push_back(v.sp.p);
  }
}

// The grid over the light vertices, and the vertices copied in its slot order: a camera vertex's
// merges then read their light vertices side by side (chasing each into the workers' blocks took
// most of merging's time).
void VcmRenderer::indexForMerging(float radius) {
  grid_.build(positions_, radius);
  std::vector<const LightVertex*> vertices;  // in positions_' order: block after block
  vertices.reserve(positions_.size());
  for (const std::vector<LightVertex>& block : workerVertices_)
    for (const LightVertex& v : block) vertices.push_back(&v);
  grid_.gatherBySlot<LightVertex>(vertices, bySlot_);
}

// Rows dealt to the workers in turn; pixel p's camera subpath connects to light subpath p. Its
// position in the pixel is point i of a (0,2)-sequence shifted per pixel (as the direct-emission
// pass's, render/renderer.cpp): the emitters' outlines, seen directly and so by one technique
// only, are resolved far better than by random positions.
void VcmRenderer::traceCameraPaths(const VcmTracer& tracer, uint64_t iteration, const HashGrid* grid) {
  runOnWorkers(workers_, [&](int w) {
    PathSample sample;
    for (int row = w; row < height_; row += workers_) {
      for (int x = 0; x < width_; ++x) {
        const uint32_t pixel = uint32_t(row) * uint32_t(width_) + uint32_t(x);
        IndependentSource u(hashKey(seed_, kCameraPathPurpose, iteration, pixel));
        Rng shift(hashKey(seed_, kPixelShiftPurpose, pixel));
        const uint32_t sx = shift.nextU32(), sy = shift.nextU32();
        const Vec2 film = positionInPixel(x, row, shiftedSobol02(uint32_t(iteration), sx, sy));
        sample.clear();
        tracer.traceCameraPath(film, u, paths_[pixel], bySlot_, grid, sample);
        workerFilms_[size_t(w)].addSample(sample);
      }
    }
  });
}

}  // namespace relt
