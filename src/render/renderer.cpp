#include "render/renderer.h"

#include <algorithm>

#include "camera/film_position.h"
#include "core/error.h"
#include "core/low_discrepancy.h"
#include "core/memory.h"
#include "parallel/workers.h"
#include "path/path_tracer.h"
#include "path/specular_chain.h"
#include "scene/scene_summary.h"

namespace relt {

void resolveDefaults(const Scene& scene, RenderSettings& s) {
  if (s.width <= 0) s.width = scene.defaults.width;
  if (s.height <= 0) s.height = scene.defaults.height;
  if (s.maxDepth <= 0) s.maxDepth = scene.defaults.maxDepth;
}

Renderer::Renderer(Scene scene, const RenderSettings& settings) : scene_(std::move(scene)), settings_(settings) {
  resolveDefaults(scene_, settings_);
  checkRenderable(scene_);
  // The film (double RGB), its reduced copy and the image must fit: refuse before allocating.
  const double filmBytes = 3.0 * 3.0 * sizeof(double) * settings_.width * double(settings_.height);
  const uint64_t memory = physicalMemoryBytes();
  if (!fitsInMemory(filmBytes, memory))
    throw InputError(scene_.file, "--width/--height",
                     std::to_string(settings_.width) + " x " + std::to_string(settings_.height) + " needs about " +
                         formatGiB(filmBytes) + " of film memory, more than fits in " + formatGiB(double(memory)));
  const PerspectiveCamera* cam = settings_.camera.empty() ? &scene_.cameras.front() : scene_.findCamera(settings_.camera);
  if (!cam) {
    std::string names;
    for (const auto& c : scene_.cameras) names += (names.empty() ? "" : ", ") + c.name;
    throw InputError(scene_.file, "--camera", "no camera named '" + settings_.camera + "' (cameras: " + names + ")");
  }
  tracer_ = std::make_unique<RayTracer>(scene_);
  lights_ = std::make_unique<LightSampler>(scene_, *tracer_);
  if (lights_->empty()) throw InputError(scene_.file, "scene", "no emitter with positive power");
  camera_ = std::make_unique<Camera>(*cam, settings_.width, settings_.height);
  PathSettings ps;
  ps.maxDepth = settings_.maxDepth;
  ps.heuristic = settings_.heuristic;
  ps.specularChainsApart = directEmissionApart(settings_);  // renderDirect estimates them
  ctx_ = std::make_unique<PathContext>(PathContext{scene_, *tracer_, *lights_, *camera_, ps, &subpathVertices_});
  for (int w = 0; w < std::max(settings_.threads, 1); ++w) workers_.push_back(std::make_unique<RowWorker>(*ctx_));
}

Renderer::RowWorker::RowWorker(const PathContext& ctx) : bdpt(ctx) {
  for (size_t i = 0; i < sources.size(); ++i) sourcePointers[i] = &sources[i];
}

uint64_t Renderer::samples() const {
  uint64_t n = 0;
  for (const auto& w : workers_) n += w->sampleCount;
  return n;
}

void Renderer::renderRow(RowEstimator estimator, uint64_t sampleIndex, int row, Film& film) {
  RowWorker& worker = *workers_.at(size_t(currentWorker()));
  auto& sources = worker.sources;
  auto& samples = worker.samples;
  const int w = settings_.width;
  constexpr int K = RayTracer::kPacketSize;
  for (int x0 = 0; x0 < w; x0 += K) {
    const int m = std::min(K, w - x0);
    Vec2 pos[K];
    for (int i = 0; i < m; ++i) {
      const uint64_t pixel = static_cast<uint64_t>(row) * w + (x0 + i);
      sources[i].reset(hashKey(settings_.seed, pixel, sampleIndex));
      const Vec2 jitter = sources[i].next2(SampleStream::Camera);
      pos[i] = positionInPixel(x0 + i, row, jitter);
      samples[i].clear();
    }
    if (estimator == RowEstimator::PathTracing) {
      // Neighbouring pixels together: their camera and first shadow rays trace as packets.
      tracePaths(*ctx_, m, pos, worker.sourcePointers.data(), samples.data());
    } else {
      for (int i = 0; i < m; ++i) worker.bdpt.trace(pos[i], sources[i], samples[i]);
    }
    for (int i = 0; i < m; ++i) film.addSample(samples[i]);
    worker.sampleCount += static_cast<uint64_t>(m);
  }
}

void Renderer::keepDirectEmissionInChains() {
  ctx_->settings.specularChainsApart = false;
  settings_.directSpp = 0;
}

void Renderer::renderDirect(int firstRow, int rowStride, Film& film, uint32_t begin, uint32_t end, bool probe) {
  const uint64_t stream = probe ? kProbeStream : kDirectStream;
  // The rank's rows are dealt to its workers (the i-th to worker i mod T), which add into the one
  // film: a pixel's samples all land in its own row, so each pixel's sum is made by one worker in
  // the order one worker would make it, and the image does not depend on the workers. A sample
  // that is not finite is counted apart (the film's own count is not shared between workers).
  const int workers = std::max(settings_.threads, 1);
  std::vector<uint64_t> dropped(size_t(workers), 0);
  runOnWorkers(workers, [&](int w) {
    IndependentSource source;
    PathSample sample;
    int i = 0;
    for (int row = firstRow; row < settings_.height; row += rowStride, ++i)
      if (i % workers == w) dropped[size_t(w)] += renderDirectRow(stream, row, film, begin, end, source, sample);
  });
  for (uint64_t n : dropped) film.addDropped(n);
}

uint64_t Renderer::renderDirectRow(uint64_t stream, int row, Film& film, uint32_t begin,
                                   uint32_t end, IndependentSource& source, PathSample& sample) const {
  // Positions from a (0,2)-sequence shifted per pixel: the error sits at the emitter's outline,
  // where a pixel is partly covered, and such points resolve a straight edge there far better
  // than a jittered grid or random positions (core/low_discrepancy.h).
  uint64_t dropped = 0;
  for (int x = 0; x < settings_.width; ++x) {
    const uint64_t pixel = static_cast<uint64_t>(row) * settings_.width + x;
    Rng shift(hashKey(settings_.seed, stream, pixel));
    const uint32_t sx = shift.nextU32(), sy = shift.nextU32();
    for (uint32_t k = begin; k < end; ++k) {
      source.reset(hashKey(settings_.seed, stream, pixel, static_cast<uint64_t>(k)));
      const Vec2 offset = shiftedSobol02(k, sx, sy);
      sample.clear();
      traceSpecularChain(*ctx_, positionInPixel(x, row, offset), source, sample);
      if (sample.finite())
        film.addSample(sample);
      else
        ++dropped;
    }
  }
  return dropped;
}

Image Renderer::resolve(const Film& film, const std::vector<double>& sums, double spp) {
  Image image(film.width(), film.height());
  const double scale = spp > 0.0 ? 1.0 / spp : 0.0;
  for (size_t i = 0; i < sums.size(); ++i) image.rgb[i] = static_cast<float>(sums[i] * scale);
  return image;
}

Image Renderer::resolve(const Film& film, const std::vector<double>& sums, int passes, int rowsAhead) {
  Image image = resolve(film, sums, double(passes));
  const size_t row = size_t(3) * film.width();
  for (size_t i = 0; i < row * size_t(std::clamp(rowsAhead, 0, film.height())); ++i)
    image.rgb[i] = static_cast<float>(sums[i] * (1.0 / double(passes + 1)));  // as resolve(passes + 1) does
  return image;
}

}  // namespace relt
