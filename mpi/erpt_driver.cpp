#include "erpt_driver.h"

#include <stdexcept>

#include "core/error.h"
#include "core/words.h"
#include "pass_loop.h"

namespace relt::mpi {
namespace {

ErptCounters sumOverRanks(const ErptCounters& local) {
  ErptCounters s = local;
  uint64_t* const fields[] = {&s.seeds, &s.chains, &s.mutations, &s.accepted, &s.invalidProposals};
  std::vector<double> v;
  for (uint64_t* f : fields) v.push_back(double(*f));
  allreduceSum(v);  // one collective; exact, counts stay far below 2^53
  for (size_t k = 0; k < v.size(); ++k) *fields[k] = uint64_t(v[k]);
  return s;
}

// The checkpoint's root part: the normaliser (a resume does not run the bootstrap again), the
// counters summed over ranks and the proposal tally, reduced here; other ranks' parts are empty.
std::vector<uint64_t> checkpointPart(const Session& session, const ErptOutcome& out, const ErptCounters& c) {
  std::vector<double> proposals = out.proposals;
  if (!proposals.empty()) reduceSumToRoot(proposals);
  WordWriter w;
  if (!session.isRoot()) return w.words();
  w.f64(out.normaliser);
  for (uint64_t v : {c.seeds, c.chains, c.mutations, c.accepted, c.invalidProposals}) w.u64(v);
  w.f64s(proposals);
  return std::move(w.words());
}

// The root takes the sums of the checkpoint, the other ranks start from zero; all take the normaliser.
PassStart restore(const Session& session, const Resumed& resumed, Film& film, ErptOutcome& out, ErptCounters& local) {
  resumed.restoreFilms({&film, 1});
  try {
    if (resumed.parts.empty()) throw std::runtime_error("the checkpoint holds no erpt state");
    WordReader in(resumed.parts[0]);
    out.normaliser = in.f64();
    ErptCounters c;
    for (uint64_t* v : {&c.seeds, &c.chains, &c.mutations, &c.accepted, &c.invalidProposals}) *v = in.u64();
    const std::vector<double> proposals = in.f64s(out.proposals.size());
    if (!in.done()) throw std::runtime_error("the checkpoint's erpt state does not match this render's");
    if (session.isRoot()) {
      local = c;
      out.proposals = proposals;
    }
  } catch (const std::runtime_error& e) {
    throw InputError(resumed.file, "", e.what());
  }
  return passStartOf(resumed.progress);
}

// The image so far on the root (empty elsewhere; collective): the film's rows by their seeds per
// pixel, the proposal filter applied if asked.
Image imageSoFar(const Session& session, const Film& film, const std::vector<double>& proposals, PassPoint at) {
  Image image = reducedPassImage(session, film, at);
  std::vector<double> tally = proposals;
  if (!tally.empty()) reduceSumToRoot(tally);
  if (session.isRoot() && !tally.empty()) applyProposalFilter(image, tally);
  return image;
}

}  // namespace

ErptOutcome runErpt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film,
                    const std::function<void(const Image&)>& snapshot, const CheckpointPlan& plan,
                    const Resumed* resumed) {
  ErptSettings es;
  es.chainLength = settings.chainLength;
  es.sizes = KelemenSizes{settings.smallStepMin, settings.smallStepMax};
  es.maxConsecutive = settings.erptMaxConsecutive;
  PtEvaluator eval(renderer.context(), settings.width, settings.height);
  const int bootstrap = 100000;
  ErptOutcome out;
  ErptCounters local;
  if (settings.erptProposalFilter) out.proposals.assign(static_cast<size_t>(settings.width) * settings.height, 0.0);
  std::vector<double>* tally = settings.erptProposalFilter ? &out.proposals : nullptr;
  PassStart start;
  if (resumed)
    start = restore(session, *resumed, film, out, local);
  else
    out.normaliser = allreduceSum(erptBootstrapSum(eval, settings.seed, bootstrap, session.rank(), session.size())) /
                     bootstrap;
  // Passes of one seed per pixel, distributed and timed as pt's.
  PassHooks hooks;
  hooks.renderUnit = [&](uint64_t pass, int row) {
    local.add(erptRow(eval, es, out.normaliser, settings.seed, pass, row, 1.0, film, tally));
  };
  if (snapshot)
    hooks.snapshot = [&](PassPoint at) {
      const Image image = imageSoFar(session, film, out.proposals, at);
      if (session.isRoot()) snapshot(image);
    };
  hooks.chunkDone = [&, lastCheckpoint = start.elapsed](PassPoint at, double elapsed, bool more, bool save) mutable {
    if (!checkpointNow(plan, elapsed, lastCheckpoint, more, save)) return;
    const ErptCounters sums = sumOverRanks(local);
    nlohmann::json progress = passProgress(at, elapsed);
    progress["mutations"] = sums.mutations;
    saveCheckpoint(plan, "erpt", progress, {&film, 1}, checkpointPart(session, out, sums));
  };
  out.end = runPasses(session, settings, hooks, start);
  if (tally) reduceSumToRoot(out.proposals);
  out.counters = sumOverRanks(local);
  return out;
}

}  // namespace relt::mpi
