// pssmlt: Kelemen's primary-sample-space Metropolis light transport over bdpt, chains in rounds.
#include "integrators/pssmlt/pssmlt_integrator.h"

#include "integrators/pssmlt/chain_render.h"

namespace relt {

const IntegratorEntry& pssmltIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "pssmlt";
    e.kind.directEmissionApart = true;
    e.kind.settingsJson = addChainCountSettingsJson;
    e.summary = "primary-sample-space Metropolis light transport";
    e.sharedOptions = {"--mutations-per-pixel", "--chains",         "--large-step-probability",
                       "--small-step-min",      "--small-step-max", "--direct-emission-spp"};
    e.render = renderChainIntegrator<ChainKind::Pssmlt>;
    return e;
  }();
  return entry;
}

}  // namespace relt
