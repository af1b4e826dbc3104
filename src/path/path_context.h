#pragma once
// Everything a path builder needs to trace one sample: the scene, its acceleration structure,
// lights, camera and the integrator settings.
#include <optional>
#include <string_view>

#include "camera/camera.h"
#include "light/lights.h"
#include "scene/ray_tracer.h"

namespace relt {

enum class MisHeuristic : uint8_t { Balance, Power };
inline const char* misHeuristicName(MisHeuristic h) { return h == MisHeuristic::Power ? "power" : "balance"; }
inline std::optional<MisHeuristic> parseMisHeuristic(std::string_view name) {
  if (name == "power") return MisHeuristic::Power;
  if (name == "balance") return MisHeuristic::Balance;
  return std::nullopt;
}

struct PathSettings {
  int maxDepth = 8;  // maximum number of path segments
  // Paths camera - specular (delta) vertices - emitter, the directly seen emission among them, are
  // left out: a pass apart estimates them (render/direct_pass.h). Only emission found by the camera
  // subpath makes such a path (no connection or merge can touch a delta vertex), so leaving them
  // out changes no other path's weight.
  bool specularChainsApart = false;
  MisHeuristic heuristic = MisHeuristic::Power;
  int rrDepth = 2;   // path tracing: Russian roulette from this many segments on (pbrt-v4 convention)
};

struct PathContext {
  const Scene& scene;
  const RayTracer& tracer;
  const LightSampler& lights;
  const Camera& camera;
  PathSettings settings;
  // Surface vertices the bidirectional subpaths reached (bdpt and vcm, camera and light ones
  // alike): their throughput is compared per vertex, where rays differ by technique. Null: not counted.
  PerWorkerCount* subpathVertices = nullptr;
};

inline void countSubpathVertices(const PathContext& ctx, uint64_t n) {
  if (ctx.subpathVertices && n) ctx.subpathVertices->add(n);
}

inline float misWeightTerm(float ratio, MisHeuristic h) { return h == MisHeuristic::Power ? ratio * ratio : ratio; }
// The heuristic's exponent beta: weights go as density^beta (1 balance, 2 power).
inline double misExponent(MisHeuristic h) { return h == MisHeuristic::Power ? 2.0 : 1.0; }

}  // namespace relt
