#include "integrators/pssmlt/chain_render.h"

#include <cstdio>

#include "integrators/output/render_outputs.h"
#include "integrators/pssmlt/pssmlt_driver.h"
#include "integrators/shared_options.h"

namespace relt {
namespace {

// mmlt: mutations and acceptance per path length.
nlohmann::json perDepthStats(const std::vector<ChainCounters>& perDepth) {
  nlohmann::json depths = nlohmann::json::array();
  for (size_t d = 0; d < perDepth.size(); ++d) {
    const ChainCounters& c = perDepth[d];
    const uint64_t proposed = c.smallProposed + c.largeProposed;
    depths.push_back({{"depth", d + 1},
                      {"mutations", proposed},
                      {"acceptance", proposed ? double(c.smallAccepted + c.largeAccepted) / proposed : 0.0}});
  }
  return depths;
}

}  // namespace

void addChainCountSettingsJson(const RenderSettings& s, nlohmann::json& j) {
  j["chains"] = s.chains;
  addChainSettingsJson(s, j);
}

void renderChains(RenderContext& c, const DirectEstimate& direct, Clock::time_point renderStart, ChainKind kind) {
  Job& job = c.job;
  const RenderSettings& settings = c.settings;
  Film film(settings.width, settings.height);
  int snapshots = 0;
  const Resumed* resumed = c.resumed ? &*c.resumed : nullptr;
  const PssmltOutcome o = runPssmlt(job, c.renderer, chainSettings(settings, direct), kind, film,
                                    [&](const std::vector<double>& sums, double d) {
    writeImages(settings, withDirect(Renderer::resolve(film, sums, d), direct.image));
    ++snapshots;
  }, c.plan, resumed);
  const Gathered g = gatherAfterRender(job, renderStart, c.renderer, film);
  if (!job.isRoot()) return;
  const double area = double(settings.width) * settings.height;
  const Image image =
      withDirect(Renderer::resolve(film, film.data(), pssmltResolveDivisor(o.totalMutations, o.normaliser, area)), direct.image);
  const uint64_t mutations = o.counters.smallProposed + o.counters.largeProposed;
  nlohmann::json j = commonStats(settings, job, g, image);
  j["nan_inf_samples_dropped"] = g.dropped + direct.dropped;
  addDirectStats(j, settings, direct);
  addMutationRates(j, mutations, g, job.size(), resumed ? resumed->progress.at("mutations").get<uint64_t>() : 0);
  j["rounds"] = o.rounds;
  j["snapshots"] = snapshots;
  j["bootstrap_samples"] = o.bootstrapSamples;
  j["normaliser"] = o.normaliser;
  j["acceptance_small"] = o.counters.smallProposed ? double(o.counters.smallAccepted) / o.counters.smallProposed : 0.0;
  j["acceptance_large"] = o.counters.largeProposed ? double(o.counters.largeAccepted) / o.counters.largeProposed : 0.0;
  j["invalid_proposals"] = o.counters.invalidProposals;
  if (!o.perDepth.empty()) j["per_depth"] = perDepthStats(o.perDepth);
  addResumedFrom(j, c.resumed);
  writeOutputs(settings, image, j, c.wallStart);
  std::fprintf(stderr, "relt: %llu mutations, %.2f s, %.3f M mutations/s; wrote %s\n",
               static_cast<unsigned long long>(mutations), g.renderSeconds,
               mutations / std::max(g.renderSeconds, 1e-9) * 1e-6, filesWritten(settings).c_str());
}

}  // namespace relt
