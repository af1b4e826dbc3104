#pragma once
// pssmlt's and mmlt's render after the direct-emission pass: the chains' image and their counters
// in stats.json.
#include "integrators/direct/direct_then_chains.h"
#include "integrators/pssmlt/pssmlt_driver.h"

namespace relt {

void renderChains(RenderContext& context, const DirectEstimate& direct, Clock::time_point renderStart,
                  ChainKind kind);

// The whole render of pssmlt or mmlt: the direct-emission pass (if apart), then the chains.
template <ChainKind kind>
void renderChainIntegrator(RenderContext& context) {
  renderDirectThenChains(context, [](RenderContext& c, const DirectEstimate& direct, Clock::time_point start) {
    renderChains(c, direct, start, kind);
  });
}

// Their settings in stats.json: the chain count, then what every Markov-chain integrator has.
void addChainCountSettingsJson(const RenderSettings& settings, nlohmann::json& j);

}  // namespace relt
