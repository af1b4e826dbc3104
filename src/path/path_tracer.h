#pragma once
// Unidirectional path tracing with next-event estimation and MIS (`pt`).
#include "core/sample_source.h"
#include "path/path_context.h"
#include "path/splat.h"

namespace relt {

// Traces one camera path through film position `film`, appending its splats (classes L0, L1, L2).
void tracePath(const PathContext& ctx, const Vec2& film, SampleSource& source, PathSample& out);

}  // namespace relt
