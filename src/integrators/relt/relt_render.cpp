#include "integrators/relt/relt_render.h"

#include <cmath>
#include <cstdio>

#include "integrators/output/render_outputs.h"
#include "integrators/relt/relt_driver.h"
#include "integrators/relt/relt_settings.h"

namespace relt {
namespace {

double ratio(uint64_t a, uint64_t b) { return b ? double(a) / double(b) : 0.0; }

// Replica exchange: the ladder's diagnostics go to stats.json (DESIGN §3.5).
nlohmann::json reltStats(const ReltOutcome& o) {
  nlohmann::json j;
  j["rounds"] = o.rounds;
  j["steps_per_chain"] = o.stepsPerChain;
  j["round_trips"] = o.roundTrips;
  j["round_trips_per_chain"] = double(o.roundTrips) / std::max(1, o.ladders * o.levels);
  j["bootstrap_samples"] = o.bootstrapSamples;
  j["loop_seconds"] = o.loopSeconds;
  j["round_collective_seconds_per_rank"] = o.roundCollectiveSeconds;
  j["placement"] = placementName(o.placement);
  j["chain_moves"] = o.chainMoves;
  j["chains_per_rank"] = o.chainsPerRank;
  j["groups"] = roundGroups(o.ladders);
  j["group_round_step_seconds_mean_per_rank"] = o.stepMean;
  j["group_round_step_seconds_deviation_per_rank"] = o.stepDeviation;
  j["group_round_finish_seconds_mean_per_rank"] = o.finishMean;
  nlohmann::json levels = nlohmann::json::array();
  for (int k = 0; k < o.levels; ++k) {
    const LevelCounters& c = o.perLevel[size_t(k)];
    nlohmann::json l;
    l["level"] = k;
    l["name"] = o.levelNames[size_t(k)];
    l["normaliser"] = o.normalisers[size_t(k)];
    l["mutations"] = c.smallProposed + c.largeProposed;
    l["acceptance_small"] = ratio(c.smallAccepted, c.smallProposed);
    l["acceptance_large"] = ratio(c.largeAccepted, c.largeProposed);
    l["invalid_proposals"] = c.invalidProposals;
    l["seconds"] = c.seconds;
    l["state_change_rate"] = o.tally.changeRate(k);
    if (k + 1 < o.levels) {
      const double a = o.tally.adjacentAcceptance(k);
      l["swap_acceptance_with_next"] = std::isnan(a) ? nlohmann::json(nullptr) : nlohmann::json(a);
    }
    levels.push_back(l);
  }
  j["levels"] = levels;
  j["levels_left_out"] = o.leftOutNames;
  return j;
}

}  // namespace

void renderRelt(RenderContext& c, const DirectEstimate& direct, Clock::time_point renderStart) {
  Job& job = c.job;
  const RenderSettings& settings = c.settings;
  const Resumed* resumed = c.resumed ? &*c.resumed : nullptr;
  const bool layers = replicaSettings(settings).perLevel;
  std::vector<Film> films;
  int snapshots = 0;
  const ReltOutcome o = runRelt(job, c.renderer, chainSettings(settings, direct), films,
                                [&](const std::vector<double>& sums, double d) {
    writeImages(settings, withDirect(Renderer::resolve(films[0], sums, d), direct.image));
    ++snapshots;
  }, c.plan, resumed);
  // The first film takes the sum of all levels; the others are reduced as layers.
  std::vector<std::vector<double>> layerSums;
  if (layers)
    for (Film& f : films) {
      layerSums.push_back(f.data());
      job.reduceSumToRoot(layerSums.back());
    }
  for (size_t k = 1; k < films.size(); ++k)
    for (size_t i = 0; i < films[0].data().size(); ++i) films[0].data()[i] += films[k].data()[i];
  const Gathered g = gatherAfterRender(job, renderStart, c.renderer, films[0]);
  if (!job.isRoot()) return;
  const Image image = withDirect(Renderer::resolve(films[0], films[0].data(), o.resolveDivisor), direct.image);
  std::vector<ImageLayer> out;
  for (size_t k = 0; k < layerSums.size(); ++k)
    out.push_back({"level" + std::to_string(k), Renderer::resolve(films[k], layerSums[k], o.resolveDivisor)});
  if (layers && !direct.image.rgb.empty()) out.push_back({"direct", direct.image});  // the layers still sum to the image
  uint64_t mutations = 0, invalid = 0, nonFinite = 0;
  for (const LevelCounters& level : o.perLevel) {
    mutations += level.smallProposed + level.largeProposed;
    invalid += level.invalidProposals;
    nonFinite += level.nonFinite;
  }
  nlohmann::json j = commonStats(settings, job, g, image);
  j["nan_inf_samples_dropped"] = nonFinite + direct.dropped;
  addDirectStats(j, settings, direct);
  j["nan_inf_samples_dropped_per_rank"] = counts(o.nonFinitePerRank);
  const uint64_t earlier =
      resumed ? resumed->progress.at("steps_per_chain").get<uint64_t>() * uint64_t(o.ladders * o.levels) : 0;
  addMutationRates(j, mutations, g, job.size(), earlier);
  j["snapshots"] = snapshots;
  j["invalid_proposals"] = invalid;
  j["relt"] = reltStats(o);
  addResumedFrom(j, c.resumed);
  writeOutputs(settings, image, j, c.wallStart, out);
  if (!settings.trace.empty())  // the scaling model's input; large, so apart from stats.json
    writeFileAtomically(settings.trace, nlohmann::json{{"group_round_step_seconds_per_rank", o.stepTrace}}.dump() + "\n");
  std::fprintf(stderr, "relt: %llu mutations in %llu rounds, %.2f s, %.3f M mutations/s, %llu round trips; wrote %s\n",
               static_cast<unsigned long long>(mutations), static_cast<unsigned long long>(o.rounds), g.renderSeconds,
               j["mutations_per_second"].get<double>() * 1e-6, static_cast<unsigned long long>(o.roundTrips),
               filesWritten(settings).c_str());
}

}  // namespace relt
