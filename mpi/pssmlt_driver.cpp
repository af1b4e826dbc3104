#include "pssmlt_driver.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "mcmc/chain_pool.h"
#include "mcmc/round_schedule.h"
#include "render/pace.h"
#include "render/schedule.h"

namespace relt::mpi {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

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

PssmltOutcome runPssmlt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film,
                        const SnapshotWriter& snapshot) {
  const auto start = Clock::now();  // a time budget counts the bootstrap too
  PssmltSettings ps;
  ps.mutationsPerPixel = settings.mutationsPerPixel.value_or(16.0);
  ps.chains = settings.chains;
  ps.largeStepProbability = settings.largeStepProbability;
  ps.sizes = KelemenSizes{settings.smallStepMin, settings.smallStepMax};
  const bool mmlt = settings.integrator == Integrator::Mmlt;
  PssEvaluator eval(renderer.context(), settings.width, settings.height);
  MmltEvaluator mmltEval(renderer.context(), settings.width, settings.height);

  // Bootstrap: sample i on rank i mod P; every rank then holds all targets (same order, same sums).
  std::vector<double> targets =
      mmlt ? mmltBootstrapTargets(mmltEval, settings.seed, ps.bootstrap, session.rank(), session.size())
           : bootstrapTargets(eval, settings.seed, ps.bootstrap, session.rank(), session.size());
  allreduceSum(targets);
  double bootstrapSum = 0.0;
  for (double t : targets) bootstrapSum += t;

  std::vector<int> mine;
  for (int c = 0; c < ps.chains; ++c)
    if (ownsChain(c, session.rank(), session.size())) mine.push_back(c);
  ChainPool pool(mmlt ? nullptr : &eval, mmlt ? &mmltEval : nullptr, targets, settings.seed, ps, mine);
  const bool anyChains = allreduceMax(pool.size() > 0 ? 1 : 0) > 0;

  const double area = double(settings.width) * settings.height;
  const RoundSchedule schedule(area, ps.chains, settings.seconds,
                               static_cast<uint64_t>(std::llround(ps.mutationsPerPixel * area)));
  auto normaliser = [&](std::vector<ChainCounters>* perDepthOut, ChainCounters* countersOut) {
    std::vector<ChainCounters> perDepth;
    for (const ChainCounters& c : pool.perDepth()) perDepth.push_back(sumOverRanks(c));
    const ChainCounters counters = sumOverRanks(pool.counters());
    if (perDepthOut) *perDepthOut = perDepth;
    if (countersOut) *countersOut = counters;
    return mmlt ? mmltNormaliser(targets, settings.maxDepth, perDepth)
                : pooledNormaliser(bootstrapSum, targets.size(), counters);
  };

  Pace pace;  // the rounds' agreed durations: one that spanned a stall does not end the render early
  double elapsed = allreduceMax(since(start)), lastSnapshot = 0.0, lastPrint = 0.0;
  const bool tty = ::isatty(STDERR_FILENO);
  uint64_t rounds = 0;
  for (;;) {
    if (!anyChains || !schedule.anotherRound(rounds, elapsed, pace.typical())) break;
    std::vector<uint64_t> steps;
    for (int c : mine) steps.push_back(schedule.doneAfter(rounds + 1, c) - schedule.doneAfter(rounds, c));
    if (pool.size() > 0) pool.run(steps, film);
    ++rounds;
    const Agreement agreed = agree(since(start));
    pace.add(agreed.elapsed - elapsed);
    elapsed = agreed.elapsed;
    if (agreed.stop) break;
    if (session.isRoot() && elapsed - lastPrint >= 1.0) {
      lastPrint = elapsed;
      const double rate = double(schedule.mutationsAfter(rounds)) / elapsed;
      std::fprintf(stderr, tty ? "\r%s" : "%s\n",
                   progressLine(schedule.fraction(rounds, elapsed), elapsed, rate, "mutations").c_str());
    }
    // A save request (interrupt.h): the image so far now, as a snapshot.
    const bool more = schedule.anotherRound(rounds, elapsed, pace.typical());
    if ((agreed.save && more) || snapshotDue(settings.snapshotEvery, elapsed, lastSnapshot, more)) {
      lastSnapshot = elapsed;
      std::vector<ChainCounters> perDepth;
      const double b = normaliser(&perDepth, nullptr);
      Film merged = film;
      if (mmlt) pool.mergeDepthFilms(mmltDepthWeights(targets, settings.maxDepth, perDepth), merged);
      std::vector<double> sums = std::move(merged.data());
      reduceSumToRoot(sums);
      if (session.isRoot()) snapshot(sums, pssmltResolveDivisor(schedule.mutationsAfter(rounds), b, area));
    }
  }

  if (session.isRoot() && tty && lastPrint > 0.0) std::fprintf(stderr, "\n");
  PssmltOutcome out;
  out.bootstrapSamples = targets.size();
  out.rounds = rounds;
  out.totalMutations = schedule.mutationsAfter(rounds);
  out.normaliser = normaliser(&out.perDepth, &out.counters);
  // mmlt: each path length's film joins the image with its own normaliser and step count.
  if (mmlt) pool.mergeDepthFilms(mmltDepthWeights(targets, settings.maxDepth, out.perDepth), film);
  return out;
}

}  // namespace relt::mpi
