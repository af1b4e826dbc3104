#include "pssmlt_driver.h"

#include <cmath>

namespace relt::mpi {
namespace {

ChainCounters sumOverRanks(const ChainCounters& c) {
  ChainCounters s;
  s.largeTargetSum = allreduceSum(c.largeTargetSum);
  s.smallProposed = allreduceSum(c.smallProposed);
  s.smallAccepted = allreduceSum(c.smallAccepted);
  s.largeProposed = allreduceSum(c.largeProposed);
  s.largeAccepted = allreduceSum(c.largeAccepted);
  s.invalidProposals = allreduceSum(c.invalidProposals);
  return s;
}

}  // namespace

PssmltOutcome runPssmlt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film) {
  PssmltSettings ps;
  ps.mutationsPerPixel = settings.mutationsPerPixel.value_or(16.0);
  ps.chains = settings.chains;
  const bool mmlt = settings.integrator == Integrator::Mmlt;
  PssEvaluator eval(renderer.context(), settings.width, settings.height);
  MmltEvaluator mmltEval(renderer.context(), settings.width, settings.height);

  // Bootstrap: sample i on rank i mod P; every rank then holds all targets (same order, same sums).
  std::vector<double> targets =
      mmlt ? mmltBootstrapTargets(mmltEval, settings.seed, ps.bootstrap, session.rank(), session.size())
           : bootstrapTargets(eval, settings.seed, ps.bootstrap, session.rank(), session.size());
  allreduceSum(targets);
  double sum = 0.0;
  for (double t : targets) sum += t;

  PssmltOutcome out;
  out.bootstrapSamples = targets.size();
  out.totalMutations =
      static_cast<uint64_t>(std::llround(ps.mutationsPerPixel * settings.width * static_cast<double>(settings.height)));
  std::vector<int> mine;
  for (int c = 0; c < ps.chains; ++c)
    if (ownsChain(c, session.rank(), session.size())) mine.push_back(c);
  std::vector<ChainCounters> perDepth;
  const ChainCounters local =
      mmlt ? runMmltChains(mmltEval, targets, settings.seed, ps, mine, out.totalMutations, film, &perDepth)
           : runChains(eval, targets, settings.seed, ps, mine, out.totalMutations, film);
  for (const ChainCounters& c : perDepth) out.perDepth.push_back(sumOverRanks(c));
  out.counters = sumOverRanks(local);
  out.normaliser = mmlt ? mmltNormaliser(targets, settings.maxDepth, out.perDepth)
                        : pooledNormaliser(sum, targets.size(), out.counters);
  return out;
}

}  // namespace relt::mpi
