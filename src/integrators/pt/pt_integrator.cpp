// pt: path tracing with next-event estimation and MIS, independent samples in passes.
#include "integrators/pt/pt_integrator.h"

#include "integrators/passes/pass_render.h"

namespace relt {

const IntegratorEntry& ptIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "pt";
    e.summary = "path tracing with next-event estimation";
    e.sharedOptions = {"--spp"};
    // A pixel's path splats into its own pixel: the rows of a pass stand alone.
    e.render = [](RenderContext& c) { renderPasses(c, RowEstimator::PathTracing, true); };
    return e;
  }();
  return entry;
}

}  // namespace relt
