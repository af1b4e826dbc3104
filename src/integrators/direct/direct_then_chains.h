#pragma once
// The render of pssmlt, mmlt, relt, vcm and meb: the emission seen directly or through specular
// surfaces only in a pass apart first (direct_driver.h; none for mmlt or with
// --direct-emission-spp 0), then the main estimator (the chains, or vcm's and meb's iterations),
// whose image it is added to. A render stopped during the pass writes the pass's image.
#include <functional>

#include "integrators/direct/direct_driver.h"
#include "integrators/integrator.h"

namespace relt {

// The chains of one integrator after the pass, given its estimate and when rendering began.
using ChainsAfterDirect = std::function<void(RenderContext&, const DirectEstimate&, Clock::time_point renderStart)>;
void renderDirectThenChains(RenderContext& context, const ChainsAfterDirect& chains);

// The chains' settings: a time budget less what the direct estimate took (at least a round runs).
RenderSettings chainSettings(RenderSettings settings, const DirectEstimate& direct);
// The chains' image plus the separately estimated directly seen emission (if any).
Image withDirect(Image image, const Image& direct);
// stats.json: the pass's rays per pixel as taken (0: no emitter in view, the chains did it) and time.
void addDirectStats(nlohmann::json& j, const RenderSettings& settings, const DirectEstimate& direct);

}  // namespace relt
