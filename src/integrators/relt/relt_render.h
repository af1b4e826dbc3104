#pragma once
// relt's render after the direct-emission pass: the ladders' image (and each level's as a layer
// with --per-level), the ladder's diagnostics in stats.json (DESIGN §3.5), the trace if asked.
#include "integrators/direct/direct_then_chains.h"

namespace relt {

void renderRelt(RenderContext& context, const DirectEstimate& direct, Clock::time_point renderStart);

}  // namespace relt
