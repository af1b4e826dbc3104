#include "erpt_driver.h"

#include <chrono>

#include "render/schedule.h"

namespace relt::mpi {

ErptOutcome runErpt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film) {
  ErptSettings es;
  es.chainLength = settings.chainLength;
  es.sizes = KelemenSizes{settings.smallStepMin, settings.smallStepMax};
  es.maxConsecutive = settings.erptMaxConsecutive;
  PtEvaluator eval(renderer.context(), settings.width, settings.height);
  const int bootstrap = 100000;
  ErptOutcome out;
  out.normaliser = allreduceSum(erptBootstrapSum(eval, settings.seed, bootstrap, session.rank(), session.size())) /
                   bootstrap;
  // Passes of one seed per pixel; a timed render decides collectively after each pass, as pt does.
  const bool timed = settings.seconds.has_value();
  const int spp = settings.spp.value_or(timed ? 0 : 16);
  ErptCounters local;
  if (settings.erptProposalFilter) out.proposals.assign(static_cast<size_t>(settings.width) * settings.height, 0.0);
  std::vector<double>* tally = settings.erptProposalFilter ? &out.proposals : nullptr;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0, lastPass = 0.0;
  int passes = 0;
  for (;;) {
    if (timed ? !startAnotherPass(passes, elapsed, lastPass, *settings.seconds) : passes >= spp) break;
    for (int row = 0; row < settings.height; ++row)
      if (ownsUnit(static_cast<uint64_t>(passes), row, settings.height, session.rank(), session.size()))
        local.add(
            erptRow(eval, es, out.normaliser, settings.seed, static_cast<uint64_t>(passes), row, 1.0, film, tally));
    ++passes;
    if (timed) {
      const double now = allreduceMax(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      lastPass = now - elapsed;
      elapsed = now;
    }
  }
  out.seedsPerPixel = passes;
  if (tally) reduceSumToRoot(out.proposals);
  out.counters.seeds = allreduceSum(local.seeds);
  out.counters.chains = allreduceSum(local.chains);
  out.counters.mutations = allreduceSum(local.mutations);
  out.counters.accepted = allreduceSum(local.accepted);
  out.counters.invalidProposals = allreduceSum(local.invalidProposals);
  return out;
}

}  // namespace relt::mpi
