// erpt: energy redistribution path tracing, seeds in passes each starting short chains that spread
// its energy over neighbouring paths.
#include "integrators/erpt/erpt_integrator.h"

#include <cstdio>

#include "integrators/erpt/erpt_driver.h"
#include "integrators/erpt/erpt_settings.h"
#include "integrators/output/render_outputs.h"
#include "integrators/shared_options.h"

namespace relt {
namespace {

void addErptOptions(CLI::App& cmd, IntegratorSettings& own) {
  auto& r = dynamic_cast<ErptIntegratorSettings&>(own);
  cmd.add_option("--chain-length", r.chainLength, "erpt: mutations per energy-redistribution chain")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd.add_option("--erpt-max-consecutive", r.maxConsecutive,
                 "erpt: stop depositing after this many mutations on one pixel (biased noise filter; 0 = off)")
      ->check(CLI::Range(0, 1 << 20))
      ->capture_default_str();
  cmd.add_flag("--erpt-proposal-filter", r.proposalFilter,
               "erpt: scale pixels by blurred / actual proposed mutations (biased noise filter)");
}

void addErptSettingsJson(const RenderSettings& s, nlohmann::json& j) {
  const auto& own = s.own.get<ErptIntegratorSettings>();
  j["chain_length"] = own.chainLength;
  if (own.maxConsecutive > 0) j["max_consecutive"] = own.maxConsecutive;
  if (own.proposalFilter) j["proposal_filter"] = true;
  j["small_step"] = smallStepJson(s);
}

// Its image (with the proposal filter, if asked) and counters in stats.json.
void renderErpt(RenderContext& c) {
  Job& job = c.job;
  const RenderSettings& settings = c.settings;
  const Resumed* resumed = c.resumed ? &*c.resumed : nullptr;
  PassFilm film = erptFilm(settings);
  const auto renderStart = Clock::now();
  int snapshots = 0;
  const ErptOutcome o = runErpt(job, c.renderer, settings, film, [&](const Image& image) {
    writeImages(settings, image);
    ++snapshots;
  }, c.plan, resumed);
  const Gathered g = gatherAfterRender(job, renderStart, c.renderer, film.live(), false);
  if (!job.isRoot()) return;
  const Image& image = o.image;
  nlohmann::json j = commonStats(settings, job, g, image);
  addMutationRates(j, o.counters.mutations, g, job.size(), resumed ? resumed->progress.at("mutations").get<uint64_t>() : 0);
  addPassStats(j, o.end, film.shown(o.end));
  j["snapshots"] = snapshots;
  j["seeds"] = o.counters.seeds;
  j["chains"] = o.counters.chains;
  j["acceptance"] = o.counters.mutations ? double(o.counters.accepted) / o.counters.mutations : 0.0;
  j["invalid_proposals"] = o.counters.invalidProposals;
  j["normaliser"] = o.normaliser;
  addResumedFrom(j, c.resumed);
  writeOutputs(settings, image, j, c.wallStart);
  std::fprintf(stderr, "relt: %d seeds per pixel%s, %llu seeds, %llu chains, %llu mutations, %.2f s; wrote %s\n",
               o.end.passes, inPassNote(o.end, film.shown(o.end)).c_str(),
               static_cast<unsigned long long>(o.counters.seeds), static_cast<unsigned long long>(o.counters.chains),
               static_cast<unsigned long long>(o.counters.mutations), g.renderSeconds, filesWritten(settings).c_str());
}

}  // namespace

const IntegratorEntry& erptIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "erpt";
    e.kind.settingsJson = addErptSettingsJson;
    e.summary = "energy redistribution path tracing";
    e.sharedOptions = {"--spp", "--small-step-min", "--small-step-max"};
    e.makeSettings = makeSettingsOf<ErptIntegratorSettings>;
    e.addOptions = addErptOptions;
    e.render = renderErpt;
    return e;
  }();
  return entry;
}

}  // namespace relt
