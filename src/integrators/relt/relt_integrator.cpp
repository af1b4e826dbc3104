// relt: replica exchange light transport, ladders of tempered or relaxed targets over primary
// sample space whose chains exchange states (src/replica).
#include "integrators/relt/relt_integrator.h"

#include "integrators/relt/relt_options.h"
#include "integrators/relt/relt_render.h"
#include "integrators/relt/relt_settings.h"

namespace relt {

const IntegratorEntry& reltIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "relt";
    e.kind.directEmissionApart = true;
    e.kind.settingsJson = addReltSettingsJson;
    e.summary = "replica exchange light transport";
    e.sharedOptions = {"--mutations-per-pixel", "--large-step-probability", "--small-step-min", "--small-step-max",
                       "--direct-emission-spp", "--trace"};
    e.makeSettings = makeSettingsOf<ReltSettings>;
    e.addOptions = addReltOptions;
    e.validate = validateReltOptions;
    e.render = [](RenderContext& c) { renderDirectThenChains(c, renderRelt); };
    return e;
  }();
  return entry;
}

}  // namespace relt
