#include "integrators/passes/iteration_loop.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "integrators/direct/direct_then_chains.h"
#include "integrators/output/render_outputs.h"
#include "mcmc/round_schedule.h"

namespace relt {

IterationLoop::IterationLoop(RenderContext& c, const char* name, Film& film, std::function<void(uint64_t)> render,
                             const DirectEstimate& direct, Clock::time_point renderStart)
    : c_(c), name_(name), film_(film), render_(std::move(render)), direct_(direct), renderStart_(renderStart),
      budgetSeconds_(chainSettings(c.settings, direct).seconds) {
  if (c.resumed) {
    c.resumed->restoreFilms(std::span<Film>(&film, 1));
    done_ = c.resumed->progress.at("iterations").get<uint64_t>();
    earlier_ = c.resumed->progress.at("elapsed").get<double>();
  }
  resumedAt_ = done_;
}

Image IterationLoop::image() {
  std::vector<double> sums = film_.data();
  c_.job.reduceSumToRoot(sums);
  if (!c_.job.isRoot()) return Image();
  return withDirect(Renderer::resolve(film_, sums, double(std::max<uint64_t>(done_, 1))), direct_.image);
}

void IterationLoop::save(double elapsed) {
  saveCheckpoint(c_.job, c_.plan, name_, {{"iterations", done_}, {"elapsed", elapsed}}, std::span<const Film>(&film_, 1),
                 {});
}

void IterationLoop::run() {
  Job& job = c_.job;
  const RenderSettings& s = c_.settings;
  const uint64_t ranks = uint64_t(job.size());
  const uint64_t budget = budgetSeconds_ ? UINT64_MAX : uint64_t(s.spp.value_or(kDefaultSpp));
  double agreed = earlier_, lastRound = 0.0, lastPrint = 0.0, lastSnapshot = earlier_, lastCheckpoint = earlier_;
  bool first = true;
  while (done_ < budget) {
    if (budgetSeconds_ && !startAnotherPass(first ? 0 : 1, agreed, lastRound, *budgetSeconds_)) break;
    first = false;
    const uint64_t i = done_ + uint64_t(job.rank());
    if (i < budget) render_(i);
    done_ = std::min(budget, done_ + ranks);
    const JobAgreement a = job.agree(earlier_ + secondsSince(start_));
    lastRound = a.elapsed - agreed;
    agreed = a.elapsed;
    const bool more = !a.stop && done_ < budget && !(budgetSeconds_ && agreed + lastRound > *budgetSeconds_);
    // A save request always writes (an image must exist before the kill); the final image is
    // written after the loop.
    if (a.save || snapshotDue(s.snapshotEvery, agreed, lastSnapshot, more)) {
      const Image snapshot = image();
      if (job.isRoot()) writeImages(s, snapshot);
      lastSnapshot = agreed;
      ++snapshots_;
    }
    if (checkpointNow(c_.plan, agreed, lastCheckpoint, more, a.save)) save(agreed);
    if (a.stop) break;
    printProgress(agreed, budget, lastPrint);
  }
  if (job.isRoot() && lastPrint > 0.0 && ::isatty(STDERR_FILENO)) std::fprintf(stderr, "\n");
}

void IterationLoop::printProgress(double agreed, uint64_t budget, double& lastPrint) const {
  if (!c_.job.isRoot() || agreed - lastPrint < 1.0) return;
  lastPrint = agreed;
  const RenderSettings& s = c_.settings;
  const double fraction = budgetSeconds_ ? agreed / *budgetSeconds_ : double(done_) / double(budget);
  // An iteration is one camera sample (and one light subpath) per pixel.
  const double samples = double(done_) * double(s.width) * double(s.height);
  std::fprintf(stderr, ::isatty(STDERR_FILENO) ? "\r%s" : "%s\n",
               progressLine(std::min(fraction, 1.0), agreed, samples / agreed, "samples").c_str());
}

void finishIterations(RenderContext& c, IterationLoop& loop, Film& film, const std::function<nlohmann::json()>& own,
                      const std::function<std::string(const nlohmann::json&, const Gathered&)>& closing) {
  Job& job = c.job;
  const Image image = loop.image();
  const nlohmann::json mine = own();
  const Gathered g = gatherAfterRender(job, loop.renderStart(), c.renderer, film, false);
  if (!job.isRoot()) return;
  nlohmann::json j = commonStats(c.settings, job, g, image);
  j.update(mine);
  j["nan_inf_samples_dropped"] = g.dropped + loop.direct().dropped;
  addDirectStats(j, c.settings, loop.direct());
  j["iterations"] = loop.done();
  j["iterations_per_second"] = double(loop.done() - loop.resumedAt()) / std::max(g.renderSeconds, 1e-9);
  j["snapshots"] = loop.snapshots();
  addResumedFrom(j, c.resumed);
  writeOutputs(c.settings, image, j, c.wallStart);
  std::fprintf(stderr, "relt: %llu iterations, %.2f s, %s; wrote %s\n", static_cast<unsigned long long>(loop.done()),
               g.renderSeconds, closing(j, g).c_str(), filesWritten(c.settings).c_str());
}

}  // namespace relt
