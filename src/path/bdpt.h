#pragma once
// Bidirectional path tracing over all (s, t) strategies with MIS (`bdpt`). s = number of light
// subpath vertices, t = number of camera subpath vertices of a strategy (Veach 1997 ch. 10).
#include <functional>
#include <span>
#include <vector>

#include "core/sample_source.h"
#include "path/path_context.h"
#include "path/splat.h"
#include "path/vertex.h"

namespace relt {

// Called for every strategy that produced a non-zero contribution (tests check MIS weights).
// `light` holds the s light vertices (for s = 1, the freshly sampled light point) and `camera`
// the t camera vertices, both in generation order; weight is the MIS weight used.
using ConnectionObserver = std::function<void(std::span<const PathVertex> light, std::span<const PathVertex> camera,
                                              float weight, const Color& contribution)>;

class Bdpt {
 public:
  explicit Bdpt(const PathContext& ctx) : ctx_(ctx) {}

  // Traces one camera subpath through `film` and one light subpath, connects them in every way.
  void trace(const Vec2& film, SampleSource& source, PathSample& out);
  void setObserver(ConnectionObserver observer) { observer_ = std::move(observer); }

  // MIS weight of strategy (s, t) for the given subpaths (densities at the connection updated
  // internally). Exposed for tests.
  float misWeight(std::span<PathVertex> light, std::span<PathVertex> camera) const;

 private:
  void randomWalk(Ray ray, Color beta, TransportMode mode, size_t maxVertices, SampleSource& source,
                  SampleStream stream, std::vector<PathVertex>& path) const;
  void generateCameraSubpath(const Vec2& film, SampleSource& source);
  void generateLightSubpath(SampleSource& source);
  void connect(int s, int t, const Vec2& film, SampleSource& source, PathSample& out);

  const PathContext& ctx_;
  std::vector<PathVertex> camera_, light_;
  ConnectionObserver observer_;
};

}  // namespace relt
