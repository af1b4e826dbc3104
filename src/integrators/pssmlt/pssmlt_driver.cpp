#include "integrators/pssmlt/pssmlt_driver.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "checkpoint/checkpoint.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/words.h"
#include "mcmc/chain_pool.h"
#include "mcmc/round_schedule.h"
#include "parallel/workers.h"
#include "render/chain_settings.h"
#include "schedule/pace.h"
#include "schedule/schedule.h"

namespace relt {
namespace {


std::vector<int> ownedChains(Job& job, int chains) {
  std::vector<int> mine;
  for (int c = 0; c < chains; ++c)
    if (ownsChain(c, job.rank(), job.size())) mine.push_back(c);
  return mine;
}

// A rank's checkpoint part: the bootstrap targets (the root's only: every rank holds the same
// ones), then the pool's chains.
std::vector<uint64_t> checkpointPart(bool root, const std::vector<double>& targets, const ChainPool& pool) {
  WordWriter t, w;
  if (root) t.f64s(targets);
  w.block(t.words());
  w.block(pool.checkpointPart());
  return std::move(w.words());
}

// The bootstrap as the checkpoint holds it (a resume does not run it again); `poolParts` gets
// every old rank's chains.
std::vector<double> restoredTargets(const Resumed& resumed, std::vector<std::vector<uint64_t>>& poolParts) {
  std::vector<double> targets;
  for (size_t r = 0; r < resumed.parts.size(); ++r) {
    WordReader in(resumed.parts[r]);
    const std::vector<uint64_t> words = in.block();
    if (r == 0) targets = WordReader(words).f64s(words.size());
    poolParts.push_back(in.block());
    if (!in.done()) throw std::runtime_error("the checkpoint's chain part has trailing data");
  }
  return targets;
}

// The chains this rank owns, started from the bootstrap or taken from a checkpoint, and the
// round loop that runs them (collective).
class ChainRender {
 public:
  ChainRender(Job& job, Renderer& renderer, const RenderSettings& settings, ChainKind kind, Film& film,
              const CheckpointPlan& plan, const Resumed* resumed);
  // Rounds until the budget is spent or the ranks agree to stop; snapshots and checkpoints between.
  void loop(const SnapshotWriter& snapshot);
  PssmltOutcome outcome();

 private:
  std::vector<double> bootstrap(const Resumed* resumed);
  void restore(const Resumed& resumed);
  double normaliser(std::vector<ChainCounters>* perDepthOut, ChainCounters* countersOut);
  void writeSnapshot(const SnapshotWriter& snapshot);
  void writeCheckpoint(double elapsed);

  Job& job_;
  const RenderSettings& settings_;
  Film& film_;
  const CheckpointPlan& plan_;
  const Clock::time_point start_ = Clock::now();  // a time budget counts the bootstrap too
  const PssmltSettings ps_;
  const bool mmlt_;
  const double area_;
  PerWorker<PssEvaluator> eval_;  // one per worker thread
  PerWorker<MmltEvaluator> mmltEval_;
  std::vector<std::vector<uint64_t>> poolParts_;  // a resume's chains, every old rank's
  std::vector<double> targets_;
  double bootstrapSum_ = 0.0;
  ChainPool pool_;
  RoundSchedule schedule_;
  uint64_t rounds_ = 0;
  double elapsed_ = 0.0;  // the agreed seconds of chain rendering, over all sittings
};

ChainRender::ChainRender(Job& job, Renderer& renderer, const RenderSettings& settings, ChainKind kind, Film& film,
                         const CheckpointPlan& plan, const Resumed* resumed)
    : job_(job),
      settings_(settings),
      film_(film),
      plan_(plan),
      ps_(pssmltSettings(settings)),
      mmlt_(kind == ChainKind::Mmlt),
      area_(double(settings.width) * settings.height),
      eval_(mmlt_ ? 0 : settings.threads, renderer.context(), settings.width, settings.height),
      mmltEval_(mmlt_ ? settings.threads : 0, renderer.context(), settings.width, settings.height),
      targets_(bootstrap(resumed)),
      pool_(mmlt_ ? nullptr : &eval_, mmlt_ ? &mmltEval_ : nullptr, targets_, settings.seed, ps_,
            ownedChains(job, ps_.chains)),
      schedule_(area_, ps_.chains, settings.seconds,
                static_cast<uint64_t>(std::llround(ps_.mutationsPerPixel * area_))) {
  for (double t : targets_) bootstrapSum_ += t;
  if (resumed) restore(*resumed);
  elapsed_ += job.allreduceMax(secondsSince(start_));
}

// Sample i on rank i mod P (and there on one of its workers); every rank then holds all targets
// (same order, same sums).
std::vector<double> ChainRender::bootstrap(const Resumed* resumed) {
  if (resumed) {
    try {
      return restoredTargets(*resumed, poolParts_);
    } catch (const std::runtime_error& e) {
      throw InputError(resumed->file, "", e.what());
    }
  }
  auto share = [&](int w, int first, int stride) {
    return mmlt_ ? mmltBootstrapTargets(mmltEval_[w], settings_.seed, ps_.bootstrap, first, stride)
                 : bootstrapTargets(eval_[w], settings_.seed, ps_.bootstrap, first, stride);
  };
  std::vector<double> targets = sumOfWorkerShares(mmlt_ ? mmltEval_.size() : eval_.size(), job_.rank(), job_.size(), share);
  job_.allreduceSum(targets);
  return targets;
}

void ChainRender::restore(const Resumed& resumed) {
  // The image film, then (mmlt, stratified) one per depth: reduced on the root, empty elsewhere.
  std::vector<Film>& depths = pool_.depthFilms(film_.width(), film_.height());
  std::vector<Film> films(1 + depths.size(), Film(film_.width(), film_.height()));
  resumed.restoreFilms(films);
  film_.data() = std::move(films[0].data());
  for (size_t d = 0; d < depths.size(); ++d) depths[d].data() = std::move(films[d + 1].data());
  try {
    if (targets_.size() != static_cast<size_t>(ps_.bootstrap)) throw std::runtime_error("the checkpoint's bootstrap is not this render's");
    pool_.restore(poolParts_);
  } catch (const std::runtime_error& e) {
    throw InputError(resumed.file, "", e.what());
  }
  poolParts_.clear();
  rounds_ = resumed.progress.at("rounds").get<uint64_t>();
  elapsed_ = resumed.progress.at("elapsed").get<double>();
}

double ChainRender::normaliser(std::vector<ChainCounters>* perDepthOut, ChainCounters* countersOut) {
  std::vector<ChainCounters> perDepth;
  for (const ChainCounters& c : pool_.perDepth()) perDepth.push_back(sumOverRanks(job_, c));
  const ChainCounters counters = sumOverRanks(job_, pool_.counters());
  if (perDepthOut) *perDepthOut = perDepth;
  if (countersOut) *countersOut = counters;
  return mmlt_ ? mmltNormaliser(targets_, settings_.maxDepth, perDepth)
               : pooledNormaliser(bootstrapSum_, targets_.size(), counters);
}

void ChainRender::writeSnapshot(const SnapshotWriter& snapshot) {
  std::vector<ChainCounters> perDepth;
  const double b = normaliser(&perDepth, nullptr);
  Film merged = film_;
  if (mmlt_) pool_.mergeDepthFilms(mmltDepthWeights(targets_, settings_.maxDepth, perDepth), merged);
  std::vector<double> sums = std::move(merged.data());
  job_.reduceSumToRoot(sums);
  if (job_.isRoot()) snapshot(sums, pssmltResolveDivisor(schedule_.mutationsAfter(rounds_), b, area_));
}

void ChainRender::writeCheckpoint(double elapsed) {
  std::vector<Film> films{film_};
  for (const Film& f : pool_.depthFilms(film_.width(), film_.height())) films.push_back(f);
  const nlohmann::json progress = {
      {"rounds", rounds_}, {"elapsed", elapsed}, {"mutations", schedule_.mutationsAfter(rounds_)}};
  saveCheckpoint(job_, plan_, settings_.integrator.name.c_str(), progress, films,
                 checkpointPart(job_.isRoot(), targets_, pool_));
}

void ChainRender::loop(const SnapshotWriter& snapshot) {
  Pace pace;  // the rounds' agreed durations: one that spanned a stall does not end the render early
  double lastSnapshot = elapsed_, lastPrint = elapsed_, lastCheckpoint = elapsed_;
  bool printed = false;
  const double sittingStart = elapsed_ - secondsSince(start_);  // this process's clock, continuing the earlier time
  const bool tty = ::isatty(STDERR_FILENO);
  const bool anyChains = job_.allreduceMax(pool_.size() > 0 ? 1 : 0) > 0;
  bool more = anyChains && schedule_.anotherRound(rounds_, elapsed_, pace.typical());
  while (more) {
    std::vector<uint64_t> steps;
    for (int c : pool_.ids())
      steps.push_back(schedule_.doneAfter(rounds_ + 1, c) - schedule_.doneAfter(rounds_, c));
    if (pool_.size() > 0) pool_.run(steps, film_);
    ++rounds_;
    const JobAgreement agreed = job_.agree(sittingStart + secondsSince(start_));
    pace.add(agreed.elapsed - elapsed_);
    elapsed_ = agreed.elapsed;
    more = !agreed.stop && schedule_.anotherRound(rounds_, elapsed_, pace.typical());
    if (job_.isRoot() && !agreed.stop && elapsed_ - lastPrint >= 1.0) {
      lastPrint = elapsed_;
      printed = true;
      const double rate = double(schedule_.mutationsAfter(rounds_)) / elapsed_;
      std::fprintf(stderr, tty ? "\r%s" : "%s\n",
                   progressLine(schedule_.fraction(rounds_, elapsed_), elapsed_, rate, "mutations").c_str());
    }
    // A save request (interrupt.h): the image so far now, as a snapshot, and a checkpoint.
    if ((agreed.save && more) || snapshotDue(settings_.snapshotEvery, elapsed_, lastSnapshot, more)) {
      lastSnapshot = elapsed_;
      writeSnapshot(snapshot);
    }
    if (checkpointNow(plan_, elapsed_, lastCheckpoint, more, agreed.save)) writeCheckpoint(elapsed_);
  }
  if (job_.isRoot() && tty && printed) std::fprintf(stderr, "\n");
}

PssmltOutcome ChainRender::outcome() {
  PssmltOutcome out;
  out.bootstrapSamples = targets_.size();
  out.rounds = rounds_;
  out.totalMutations = schedule_.mutationsAfter(rounds_);
  out.normaliser = normaliser(&out.perDepth, &out.counters);
  // mmlt: each path length's film joins the image with its own normaliser and step count.
  if (mmlt_) pool_.mergeDepthFilms(mmltDepthWeights(targets_, settings_.maxDepth, out.perDepth), film_);
  return out;
}

}  // namespace

ChainCounters sumOverRanks(Job& job, const ChainCounters& c) {
  ChainCounters s = c;
  uint64_t* const counts[] = {&s.smallProposed, &s.smallAccepted, &s.largeProposed, &s.largeAccepted,
                              &s.invalidProposals};
  std::vector<double> v = {s.largeTargetSum};
  for (uint64_t* n : counts) v.push_back(double(*n));
  job.allreduceSum(v);  // one collective (mmlt sums one per path length); counts stay far below 2^53
  s.largeTargetSum = v[0];
  for (size_t k = 0; k < std::size(counts); ++k) *counts[k] = uint64_t(v[k + 1]);
  return s;
}

PssmltOutcome runPssmlt(Job& job, Renderer& renderer, const RenderSettings& settings, ChainKind kind, Film& film,
                        const SnapshotWriter& snapshot, const CheckpointPlan& plan, const Resumed* resumed) {
  ChainRender render(job, renderer, settings, kind, film, plan, resumed);
  render.loop(snapshot);
  return render.outcome();
}

}  // namespace relt
