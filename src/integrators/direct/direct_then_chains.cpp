#include "integrators/direct/direct_then_chains.h"

#include <algorithm>
#include <cstdio>

#include "integrators/output/render_outputs.h"

namespace relt {
namespace {

// Stopped during the direct-emission pass: the image of the pass so far (the chains have not
// started; its checkpoint is written), and the stats.
void finishInThePass(RenderContext& c, Clock::time_point renderStart, const DirectEstimate& direct) {
  const RenderSettings& settings = c.settings;
  Film none(settings.width, settings.height);
  const Gathered g = gatherAfterRender(c.job, renderStart, c.renderer, none);
  if (!c.job.isRoot()) return;
  const Image image = direct.spp > 0 ? direct.image : Renderer::resolve(none, none.data(), 1.0);
  nlohmann::json j = commonStats(settings, c.job, g, image);
  j["nan_inf_samples_dropped"] = direct.dropped;
  addDirectStats(j, settings, direct);
  writeOutputs(settings, image, j, c.wallStart);
  std::fprintf(stderr, "relt: stopped in the direct-emission pass (%d rays per pixel), %.2f s; wrote %s\n", direct.spp,
               g.renderSeconds, filesWritten(settings).c_str());
}

}  // namespace

void renderDirectThenChains(RenderContext& c, const ChainsAfterDirect& chains) {
  const auto renderStart = Clock::now();
  const DirectEstimate direct = directEmission(c.job, c.renderer, c.settings, c.plan, c.resumed,
                                               [&](const Image& image) { writeImages(c.settings, image); });
  if (direct.stopped) {
    finishInThePass(c, renderStart, direct);
    return;
  }
  if (directEmissionApart(c.settings)) {
    c.plan.direct = direct.progress();
    if (direct.spp > 0) c.plan.directFilm = &direct.film;
  }
  chains(c, direct, renderStart);
}

RenderSettings chainSettings(RenderSettings s, const DirectEstimate& direct) {
  if (s.seconds) s.seconds = std::max(1e-3, *s.seconds - direct.seconds);
  return s;
}

Image withDirect(Image image, const Image& direct) {
  if (!direct.rgb.empty()) image.add(direct);
  return image;
}

void addDirectStats(nlohmann::json& j, const RenderSettings& settings, const DirectEstimate& direct) {
  if (!directEmissionApart(settings)) return;
  j["direct_emission_spp"] = direct.spp;
  j["direct_emission_seconds"] = direct.seconds;
}

}  // namespace relt
