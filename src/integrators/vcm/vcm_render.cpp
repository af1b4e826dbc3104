#include "integrators/vcm/vcm_render.h"

#include <algorithm>
#include <cstdio>

#include "integrators/direct/direct_then_chains.h"
#include "integrators/passes/iteration_loop.h"
#include "integrators/vcm/vcm_settings.h"

namespace relt {
namespace {

void renderVcmIterations(RenderContext& c, const DirectEstimate& direct, Clock::time_point renderStart) {
  const RenderSettings& settings = c.settings;
  const VcmSettings& own = settings.own.get<VcmIntegratorSettings>().vcm;
  VcmRenderer vcm(c.renderer.context(), own, settings.seed, settings.width, settings.height, settings.threads);
  Film film(settings.width, settings.height);
  IterationLoop loop(c, "vcm", film, [&](uint64_t i) { vcm.render(i, film); }, direct, renderStart);
  loop.run();
  const auto stats = [&] {
    const uint64_t last = loop.done() > 0 ? loop.done() - 1 : 0;
    return nlohmann::json{{"light_vertices", c.job.allreduceSum(vcm.lightVertices())},
                          {"merges", c.job.allreduceSum(vcm.merges())},
                          {"radius_first", vcm.firstRadius()},
                          {"radius_last", vcmRadius(vcm.firstRadius(), own.alpha, last)}};
  };
  const auto closing = [](const nlohmann::json& j, const Gathered& g) {
    const double seconds = std::max(g.renderSeconds, 1e-9);
    char line[128];
    std::snprintf(line, sizeof line, "%.3f M light vertices/s, %.2f M rays/s",
                  double(j["light_vertices"].get<uint64_t>()) / seconds * 1e-6, double(g.rays) / seconds * 1e-6);
    return std::string(line);
  };
  finishIterations(c, loop, film, stats, closing);
}

}  // namespace

void renderVcm(RenderContext& c) { renderDirectThenChains(c, renderVcmIterations); }

}  // namespace relt
