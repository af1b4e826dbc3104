#include "erpt_driver.h"

#include "render/schedule.h"

namespace relt::mpi {

ErptOutcome runErpt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film) {
  ErptSettings es;
  es.chainLength = settings.chainLength;
  es.sizes = KelemenSizes{settings.smallStepMin, settings.smallStepMax};
  PtEvaluator eval(renderer.context(), settings.width, settings.height);
  const int bootstrap = 100000;
  ErptOutcome out;
  out.normaliser = allreduceSum(erptBootstrapSum(eval, settings.seed, bootstrap, session.rank(), session.size())) /
                   bootstrap;
  out.seedsPerPixel = settings.spp.value_or(16);
  ErptCounters local;
  for (int k = 0; k < out.seedsPerPixel; ++k)
    for (int row = 0; row < settings.height; ++row)
      if (ownsUnit(static_cast<uint64_t>(k), row, settings.height, session.rank(), session.size()))
        local.add(erptRow(eval, es, out.normaliser, settings.seed, static_cast<uint64_t>(k), row, 1.0, film));
  out.counters.seeds = allreduceSum(local.seeds);
  out.counters.chains = allreduceSum(local.chains);
  out.counters.mutations = allreduceSum(local.mutations);
  out.counters.accepted = allreduceSum(local.accepted);
  out.counters.invalidProposals = allreduceSum(local.invalidProposals);
  return out;
}

}  // namespace relt::mpi
