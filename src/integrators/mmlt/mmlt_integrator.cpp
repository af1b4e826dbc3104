// mmlt: multiplexed Metropolis light transport, a chain's state choosing the path length and the
// bdpt strategy; the pssmlt machinery runs it (integrators/pssmlt).
#include "integrators/mmlt/mmlt_integrator.h"

#include "integrators/pssmlt/chain_render.h"

namespace relt {

const IntegratorEntry& mmltIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "mmlt";
    e.kind.settingsJson = addChainCountSettingsJson;
    e.summary = "multiplexed Metropolis light transport";
    e.sharedOptions = {"--mutations-per-pixel", "--chains", "--large-step-probability", "--small-step-min",
                       "--small-step-max"};
    e.render = renderChainIntegrator<ChainKind::Mmlt>;
    return e;
  }();
  return entry;
}

}  // namespace relt
