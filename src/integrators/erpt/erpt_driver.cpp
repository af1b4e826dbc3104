#include "integrators/erpt/erpt_driver.h"

#include <algorithm>
#include <stdexcept>

#include "core/error.h"
#include "core/words.h"
#include "integrators/erpt/erpt_settings.h"
#include "integrators/passes/pass_loop.h"
#include "parallel/workers.h"
#include "pss/chain_defaults.h"

namespace relt {
namespace {

ErptCounters sumOverRanks(Job& job, const ErptCounters& local) {
  ErptCounters s = local;
  uint64_t* const fields[] = {&s.seeds, &s.chains, &s.mutations, &s.accepted, &s.invalidProposals};
  std::vector<double> v;
  for (uint64_t* f : fields) v.push_back(double(*f));
  job.allreduceSum(v);  // one collective; exact, counts stay far below 2^53
  for (size_t k = 0; k < v.size(); ++k) *fields[k] = uint64_t(v[k]);
  return s;
}

// The checkpoint's root part at `at`: the normaliser (a resume does not run the bootstrap again),
// the counters summed over ranks and the proposal tallies, reduced here; other ranks' parts are empty.
std::vector<uint64_t> checkpointPart(Job& job, const PassFilm& film, PassPoint at, double normaliser,
                                     const ErptCounters& c) {
  std::vector<std::vector<double>> tallies;
  for (const std::vector<double>& t : film.checkpointTallies(at)) {
    tallies.push_back(t);
    job.reduceSumToRoot(tallies.back());
  }
  WordWriter w;
  if (!job.isRoot()) return w.words();
  w.f64(normaliser);
  for (uint64_t v : {c.seeds, c.chains, c.mutations, c.accepted, c.invalidProposals}) w.u64(v);
  for (const std::vector<double>& t : tallies) w.f64s(t);
  return std::move(w.words());
}

// The root takes the sums of the checkpoint, the other ranks start from zero; all take the normaliser.
PassStart restore(Job& job, const Resumed& resumed, PassFilm& film, ErptOutcome& out,
                  ErptCounters& local) {
  const PassStart start = passStartOf(resumed.progress);
  resumed.restoreFilms(film.checkpointFilms(start.at));
  try {
    if (resumed.parts.empty()) throw std::runtime_error("the checkpoint holds no erpt state");
    WordReader in(resumed.parts[0]);
    out.normaliser = in.f64();
    ErptCounters c;
    for (uint64_t* v : {&c.seeds, &c.chains, &c.mutations, &c.accepted, &c.invalidProposals}) *v = in.u64();
    std::vector<std::vector<double>> tallies;
    for (const std::vector<double>& t : film.checkpointTallies(start.at)) tallies.push_back(in.f64s(t.size()));
    if (!in.done()) throw std::runtime_error("the checkpoint's erpt state does not match this render's");
    if (job.isRoot()) {
      local = c;
      for (size_t k = 0; k < tallies.size(); ++k) film.checkpointTallies(start.at)[k] = std::move(tallies[k]);
    }
  } catch (const std::runtime_error& e) {
    throw InputError(resumed.file, "", e.what());
  }
  film.restored(start.at);
  return start;
}

// The image at `at` on the root (empty elsewhere; collective): what the film shows there, by its
// seeds per pixel, the proposal filter applied if asked.
Image imageSoFar(Job& job, const PassFilm& film, PassPoint at) {
  Image image = reducedPassImage(job, film, at);
  std::vector<double> tally = film.tallyShown(at);
  if (tally.empty()) return image;
  job.reduceSumToRoot(tally);
  if (job.isRoot()) applyProposalFilter(image, tally);
  return image;
}

}  // namespace

PassFilm erptFilm(const RenderSettings& settings) {
  const size_t pixels = size_t(settings.width) * settings.height;
  // A chain wanders out of its seed's row: the rows of a pass do not stand alone.
  return PassFilm(settings.width, settings.height, false,
                  settings.own.get<ErptIntegratorSettings>().proposalFilter ? pixels : 0, settings.threads);
}

ErptOutcome runErpt(Job& job, Renderer& renderer, const RenderSettings& settings, PassFilm& film,
                    const std::function<void(const Image&)>& snapshot, const CheckpointPlan& plan,
                    const Resumed* resumed) {
  const ErptSettings es = erptSettings(settings);
  PtEvaluator eval(renderer.context(), settings.width, settings.height);
  const int bootstrap = kBootstrapPaths;
  ErptOutcome out;
  ErptCounters local;
  PassStart start;
  if (resumed)
    start = restore(job, *resumed, film, out, local);
  else
    out.normaliser = job.allreduceSum(erptBootstrapSum(eval, settings.seed, bootstrap, job.rank(), job.size())) /
                     bootstrap;
  // Passes of one seed per pixel, distributed and timed as pt's.
  PassHooks hooks;
  std::vector<ErptCounters> byWorker(size_t(std::max(settings.threads, 1)));
  hooks.renderUnit = [&](uint64_t pass, int row) {
    const int w = currentWorker();
    byWorker[size_t(w)].add(erptRow(eval, es, out.normaliser, settings.seed, pass, row, 1.0, film.workerFilm(w),
                                    film.workerTally(w)));
  };
  auto counted = [&] {  // this rank's counters: the checkpoint's (root) and every worker's
    ErptCounters c = local;
    for (const ErptCounters& w : byWorker) c.add(w);
    return c;
  };
  // This run's mutations per second (a resumed root's counters hold the earlier runs' too).
  hooks.rate = [&, earlier = local.mutations, since = start.elapsed](double elapsed) {
    return double(counted().mutations - earlier) * job.size() / std::max(elapsed - since, 1e-9);
  };
  hooks.rateUnit = "mutations";
  if (snapshot)
    hooks.snapshot = [&](PassPoint at) {
      const Image image = imageSoFar(job, film, at);
      if (job.isRoot()) snapshot(image);
    };
  hooks.chunkDone = [&, lastCheckpoint = start.elapsed](PassPoint at, double elapsed, bool more, bool save) mutable {
    if (!checkpointNow(plan, elapsed, lastCheckpoint, more, save)) return;
    film.gatherWorkers();
    const ErptCounters sums = sumOverRanks(job, counted());
    nlohmann::json progress = passProgress(at, elapsed);
    progress["mutations"] = sums.mutations;
    saveCheckpoint(job, plan, "erpt", progress, film.checkpointFilms(at),
                   checkpointPart(job, film, at, out.normaliser, sums));
  };
  out.end = runPasses(job, settings, film, hooks, start);
  out.image = imageSoFar(job, film, out.end);
  out.counters = sumOverRanks(job, counted());
  return out;
}

}  // namespace relt
