#pragma once
// Bidirectional path tracing over all (s, t) strategies with MIS (`bdpt`). s = number of light
// subpath vertices, t = number of camera subpath vertices of a strategy (Veach 1997 ch. 10).
#include <functional>
#include <span>
#include <vector>

#include "core/sample_source.h"
#include "path/path_context.h"
#include "path/splat.h"
#include "path/connection_hook.h"
#include "path/vertex.h"

namespace relt {

// Called for every strategy that produced a non-zero contribution (tests check MIS weights).
// `light` holds the s light vertices (for s = 1, the freshly sampled light point) and `camera`
// the t camera vertices, both in generation order; weight is the MIS weight used.
using ConnectionObserver = std::function<void(std::span<const PathVertex> light, std::span<const PathVertex> camera,
                                              float weight, const Color& contribution)>;

struct BdptConnection;  // one strategy's connection (bdpt.cpp)

class Bdpt {
 public:
  // roulette = false: subpaths continue until they leave the scene or reach their length (MMLT
  // needs subpaths of an exact length); the densities then carry no continuation probability.
  explicit Bdpt(const PathContext& ctx, bool roulette = true) : ctx_(ctx), roulette_(roulette) {}

  // Traces one camera subpath through `film` and one light subpath, connects them in every way.
  void trace(const Vec2& film, SampleSource& source, PathSample& out);
  // One strategy only: a camera subpath of exactly t vertices and a light subpath of exactly s,
  // connected (multiplexed MLT). False if a subpath ended early or the connection gave nothing.
  bool traceStrategy(int s, int t, const Vec2& film, SampleSource& source, PathSample& out);
  void setObserver(ConnectionObserver observer) { observer_ = std::move(observer); }
  // trace() shows the hook every strategy's connection (path/connection_hook.h). Null: plain BDPT.
  void setConnectionHook(ConnectionHook* hook) { hook_ = hook; }

  // MIS weight of strategy (s, t) for the given subpaths (densities at the connection updated
  // internally). lightEnd / cameraEnd replace the BSDFs of the connection vertices (a hook's).
  // Exposed for tests.
  float misWeight(std::span<PathVertex> light, std::span<PathVertex> camera, const Bsdf* lightEnd = nullptr,
                  const Bsdf* cameraEnd = nullptr) const;

 private:
  void randomWalk(Ray ray, Color beta, TransportMode mode, size_t maxVertices, SampleSource& source,
                  SampleStream stream, std::vector<PathVertex>& path) const;
  void generateCameraSubpath(const Vec2& film, SampleSource& source, size_t maxVertices);
  void generateLightSubpath(SampleSource& source, size_t maxVertices);
  void connect(int s, int t, const Vec2& film, SampleSource& source, PathSample& out);
  // The camera subpath's first vertex after the camera that is not a specular surface (its size
  // when there is none).
  int firstSmoothCameraVertex() const;

  const PathContext& ctx_;
  bool roulette_ = true;
  std::vector<PathVertex> camera_, light_;
  ConnectionObserver observer_;
  ConnectionHook* hook_ = nullptr;
};

}  // namespace relt
