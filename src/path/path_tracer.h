#pragma once
// Unidirectional path tracing with next-event estimation and MIS (`pt`).
#include "core/sample_source.h"
#include "path/path_context.h"
#include "path/splat.h"

namespace relt {

// Traces one camera path through film position `film`, appending its splats (classes L0, L1, L2).
void tracePath(const PathContext& ctx, const Vec2& film, SampleSource& source, PathSample& out);

// Traces n camera paths (film[i], sources[i] -> out[i]), each exactly as tracePath would. Their
// camera rays and first shadow rays go to the ray tracer in packets: for neighbouring pixels those
// rays are coherent, and a packet costs little more than one ray.
void tracePaths(const PathContext& ctx, int n, const Vec2* film, SampleSource* const* sources, PathSample* out);

}  // namespace relt
