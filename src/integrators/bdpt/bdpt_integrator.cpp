// bdpt: bidirectional path tracing with MIS over every connection, independent samples in passes.
#include "integrators/bdpt/bdpt_integrator.h"

#include "integrators/passes/pass_render.h"

namespace relt {

const IntegratorEntry& bdptIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "bdpt";
    e.summary = "bidirectional path tracing";
    e.sharedOptions = {"--spp"};
    // Light paths connected to the camera splat into any row.
    e.render = [](RenderContext& c) { renderPasses(c, RowEstimator::Bidirectional, false); };
    return e;
  }();
  return entry;
}

}  // namespace relt
