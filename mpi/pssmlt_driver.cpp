#include "pssmlt_driver.h"

#include <cmath>

namespace relt::mpi {

PssmltOutcome runPssmlt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film) {
  PssmltSettings ps;
  ps.mutationsPerPixel = settings.mutationsPerPixel.value_or(16.0);
  ps.chains = settings.chains;
  PssEvaluator eval(renderer.context(), settings.width, settings.height);

  // Bootstrap: sample i on rank i mod P; every rank then holds all targets (same order, same sums).
  std::vector<double> targets = bootstrapTargets(eval, settings.seed, ps.bootstrap, session.rank(), session.size());
  allreduceSum(targets);
  double sum = 0.0;
  for (double t : targets) sum += t;

  PssmltOutcome out;
  out.bootstrapSamples = targets.size();
  out.normaliser = sum / static_cast<double>(targets.size());
  out.totalMutations =
      static_cast<uint64_t>(std::llround(ps.mutationsPerPixel * settings.width * static_cast<double>(settings.height)));
  std::vector<int> mine;
  for (int c = 0; c < ps.chains; ++c)
    if (ownsChain(c, session.rank(), session.size())) mine.push_back(c);
  const ChainCounters local = runChains(eval, targets, settings.seed, ps, mine, out.totalMutations, film);
  out.counters.smallProposed = allreduceSum(local.smallProposed);
  out.counters.smallAccepted = allreduceSum(local.smallAccepted);
  out.counters.largeProposed = allreduceSum(local.largeProposed);
  out.counters.largeAccepted = allreduceSum(local.largeAccepted);
  out.counters.invalidProposals = allreduceSum(local.invalidProposals);
  return out;
}

}  // namespace relt::mpi
