#include "erpt_driver.h"

#include "pass_loop.h"

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
  // Passes of one seed per pixel, distributed and timed as pt's.
  ErptCounters local;
  if (settings.erptProposalFilter) out.proposals.assign(static_cast<size_t>(settings.width) * settings.height, 0.0);
  std::vector<double>* tally = settings.erptProposalFilter ? &out.proposals : nullptr;
  const int passes = runPasses(session, settings, [&](uint64_t pass, int row) {
    local.add(erptRow(eval, es, out.normaliser, settings.seed, pass, row, 1.0, film, tally));
  });
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
