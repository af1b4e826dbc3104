#pragma once
// The paths camera - specular (delta) vertices - emitter, the directly seen emission among them:
// the camera ray and then only delta scatterings, the emission found at every vertex on the way.
// Only the camera subpath can make such a path, so the integrators that leave them out
// (PathSettings::specularChainsApart) get them from this pass.
#include "core/sample_source.h"
#include "path/path_context.h"
#include "path/splat.h"

namespace relt {

// Traces the chain through film position `film` until it reaches a non-specular surface, leaves
// the scene or has maxDepth segments; appends its emission (class L1 seen directly, L0 after a
// specular bounce).
void traceSpecularChain(const PathContext& ctx, const Vec2& film, SampleSource& source, PathSample& out);

}  // namespace relt
